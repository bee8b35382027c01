// Benchmark driver (not a test) for tests/performance/peer_fenicsx.py: runs
// a static scene file and prints, in full precision, the displacement at
// the mesh vertex nearest to a given point, the Newton iterations and the
// wall time of the run's assembly and linear-solve timer sections. The
// script runs the same mesh and energy in FEniCSx beside it.
//
//   build/tests/performance/peer_beam scene.prm x y z
//
// Output (one "key value..." line each): unknowns, increments,
// newton_iterations, assembly_seconds, solve_seconds, total_seconds,
// vertex x y z (the vertex used), displacement ux uy uz.

#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/simulation/static_simulation.h>

#include <iomanip>
#include <iostream>
#include <sstream>

using namespace dealii;
using namespace TissueContact;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc != 5)
    {
      std::cerr << "usage: peer_beam scene.prm x y z" << std::endl;
      return 2;
    }
  try
    {
      const Point<3> target(std::stod(argv[2]),
                            std::stod(argv[3]),
                            std::stod(argv[4]));
      const auto     parameters = Scene::SceneParameters::from_file(argv[1]);
      std::ostringstream log;
      StaticSimulation   sim(parameters, log);
      const auto         statistics = sim.run();
      const auto        &times      = sim.section_times();
      const auto         seconds    = [&](const std::string &name) {
        const auto it = times.find(name);
        return it == times.end() ? 0. : it->second;
      };

      // the vertex nearest to the target: its three DoFs (P1 or P2, the
      // vertex DoFs are the displacement there)
      const auto &disc = sim.problem().discretization();
      const auto  X    = disc.support_points();
      const auto  comp = disc.dof_components();
      const auto  u    = sim.problem().displacement(sim.solution());
      double      best = std::numeric_limits<double>::max();
      for (types::global_dof_index i = 0; i < X.size(); ++i)
        best = std::min(best, X[i].distance(target));
      Point<3>     vertex;
      Tensor<1, 3> d;
      for (types::global_dof_index i = 0; i < X.size(); ++i)
        if (X[i].distance(target) == best)
          {
            vertex     = X[i];
            d[comp[i]] = u[i];
          }

      std::cout << std::setprecision(17) << "unknowns " << u.size() << "\n"
                << "increments " << statistics.increments << "\n"
                << "newton_iterations " << statistics.newton_iterations << "\n"
                << "assembly_seconds " << seconds("assembly") << "\n"
                << "solve_seconds " << seconds("linear solve") << "\n"
                << "total_seconds " << seconds("total") << "\n"
                << "vertex " << vertex << "\n"
                << "displacement " << d << std::endl;
    }
  catch (const std::exception &e)
    {
      std::cerr << "peer_beam: " << error_message(e) << std::endl;
      return 1;
    }
  return 0;
}
