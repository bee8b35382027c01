// The knee of prm/knee_flexion.prm on the coarse mesh of meshes/knee.geo
// (h 0.06: 4 739 tetrahedra, 1 559 vertices) flexed to 90 degrees in
// 30 increments of 3 degrees: femur fixed, tibia rotated, the patella a free
// rigid body held by its ligament and tendon, the skin-fat layer sliding
// over everything and folding onto itself behind the knee. The log prints
// the angle reached, whether the cut-backs and Newton iterations stay within
// bounds (the counts go to the console: they vary with the rounding), whether
// the largest penetration stays below 10 % of the local element size, and the
// patella's motion: it must travel down and around the condyles (its center
// moves backwards and down, it turns with the tibia).

#include "scenes.h"

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const double      angle = 90.;
  const std::string prm   = project_prm(
    "knee_flexion.prm",
    {{"-setnumber h 0.0125 -setnumber n_2pi 8",
        "-setnumber h 0.06 -setnumber n_2pi 5 -setnumber pat_refine 2"},
       {"Rotation angle  = -150", "Rotation angle  = -90"},
       {"increment = 0.02", "increment = 0.0333333333333"}});
  std::ostringstream log;
  StaticSimulation   sim(Scene::SceneParameters::from_string(prm), log);
  SolveStatistics    statistics;
  if (!SceneTests::solve_or_log(sim, statistics, "the flexion"))
    return 0;
  const Problem     &problem     = sim.problem();
  const auto        &u           = sim.solution();
  const auto        &rigid       = *problem.free_rigid_bodies();
  const Tensor<1, 3> t           = rigid.translation(u, 0);
  const Tensor<1, 3> theta       = rigid.rotation_vector(u, 0);
  const double       penetration = problem.max_relative_penetration(u);

  deallog << "mesh: " << problem.get_scene().triangulation.n_active_cells()
          << " tetrahedra, " << problem.n_dofs() << " unknowns, "
          << problem.contact_assembler()->n_triangles() << " contact triangles"
          << std::endl;
  SceneTests::log_effort(statistics,
                         "flexed to " + std::to_string(int(angle)) + " degrees",
                         15,
                         2000);
  SceneTests::log_penetration(penetration);
  deallog << "patella: center moved by " << std::fixed << std::setprecision(1)
          << 1000. * t << " mm (|t| = " << 1000. * t.norm()
          << " mm), turned by " << theta.norm() * 180. / M_PI
          << " degrees about " << std::setprecision(2) << theta / theta.norm()
          << std::endl;
}
