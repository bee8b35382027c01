// The coiling snake of prm/coiling_snake.prm (meshes/coiling_snake.geo at
// h 0.02: 1 143 tetrahedra): the tail held, the head carried round a full
// turn and laid across the tail's first part. The log prints the turn
// reached, increments, cut-backs, Newton iterations, the largest
// penetration as a fraction of the local element size (must stay below
// 0.1) and the self-contact energy at the end (positive: the snake rests on
// itself).

#include "scenes.h"

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  std::ostringstream log;
  StaticSimulation   sim(
    Scene::SceneParameters::from_string(project_prm("coiling_snake.prm")), log);
  SolveStatistics statistics;
  if (!SceneTests::solve_or_log(sim, statistics, "the coiling"))
    return 0;
  const Problem      &problem = sim.problem();
  const auto         &u       = sim.solution();
  std::vector<double> contact_energy;
  problem.energy(u, 1., contact_energy);
  const double penetration = problem.max_relative_penetration(u);
  deallog << "mesh: " << problem.get_scene().triangulation.n_active_cells()
          << " tetrahedra, " << problem.contact_assembler()->n_triangles()
          << " contact triangles" << std::endl
          << "head turned 360 degrees in " << statistics.increments
          << " increments (" << statistics.cutbacks << " cut back), "
          << statistics.newton_iterations << " Newton iterations" << std::endl
          << "largest penetration / local element size " << std::setprecision(2)
          << penetration
          << " (below 0.1: " << (penetration < 0.1 ? "yes" : "no") << ")"
          << std::endl
          << "self-contact energy at the end " << scientific(contact_energy[0])
          << " (the snake rests on itself: "
          << (contact_energy[0] > 0. ? "yes" : "no") << ")" << std::endl;
}
