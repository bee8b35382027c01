// The snake swallowing an apple of prm/apple_snake.prm on a coarser mesh
// of meshes/apple_snake.geo (h 0.025, h_in 0.011): the mouth held, the
// belly in the ground plane, a rigid apple pushed from the mouth along a
// zigzag path 0.4 m toward the tail through a lumen 0.6 times its width.
// The log prints the path's end reached, whether the cut-backs and Newton
// iterations stay within bounds (the counts go to the console: they vary
// with the rounding), whether the largest penetration stays below 0.1 of
// the local element size, whether the contact energy at the end is positive
// (the apple presses the lumen) and the snake's width around the apple at the
// end against its undeformed width (the snake widens).

#include "scenes.h"

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const std::string prm = project_prm(
    "apple_snake.prm",
    {{"set File   = ../meshes/apple_snake.geo",
      "set File   = ../meshes/apple_snake.geo\n"
      "  set Gmsh options = -setnumber h 0.025 -setnumber h_in 0.011"}});
  std::ostringstream log;
  StaticSimulation   sim(Scene::SceneParameters::from_string(prm), log);
  SolveStatistics    statistics;
  if (!SceneTests::solve_or_log(sim, statistics, "the apple"))
    return 0;
  const Problem      &problem = sim.problem();
  const auto         &u       = sim.solution();
  std::vector<double> contact_energy;
  problem.energy(u, 1., contact_energy);
  const double penetration = problem.max_relative_penetration(u);

  // the snake's width (extent in y of its deformed nodes) where the apple's
  // centre ends, x = 0.435
  const double         x_end = 0.435, R = 0.045;
  const Vector<double> v     = problem.displacement(u);
  double               y_min = 1., y_max = -1.;
  for (const auto &cell :
       problem.discretization().dof_handler.active_cell_iterators())
    if (cell->material_id() == 1)
      for (const unsigned int k : cell->vertex_indices())
        {
          const Point<3> &X  = cell->vertex(k);
          const double    xk = X[0] + v[cell->vertex_dof_index(k, 0)];
          const double    yk = X[1] + v[cell->vertex_dof_index(k, 1)];
          if (std::abs(xk - x_end) < 0.01)
            {
              y_min = std::min(y_min, yk);
              y_max = std::max(y_max, yk);
            }
        }

  deallog << "mesh: " << problem.get_scene().triangulation.n_active_cells()
          << " tetrahedra, " << problem.contact_assembler()->n_triangles()
          << " contact triangles" << std::endl;
  SceneTests::log_effort(statistics,
                         "apple pushed along its whole path",
                         25,
                         2500);
  SceneTests::log_penetration(penetration);
  std::cout << "contact energy at the end " << contact_energy[0] << " + "
            << contact_energy[1] << std::endl;
  deallog << "contact energy at the end positive (the apple presses the "
             "lumen): "
          << (contact_energy[0] + contact_energy[1] > 0. ? "yes" : "no")
          << std::endl
          // to the nearest 5 mm: the last millimetre moves with the path
          // the contact takes (rounding of the tangent)
          << "snake's width at the apple "
          << 5 * static_cast<int>(std::round(200. * (y_max - y_min)))
          << " mm to 5 mm, undeformed "
          << static_cast<int>(std::round(1000. * 2 * R))
          << " mm (widened: " << (y_max - y_min > 2 * R ? "yes" : "no") << ")"
          << std::endl;
}
