// Shared by the scene tests: for the showcase ones (the knee, the snakes),
// solve a scene quietly and log where it stopped instead of failing without
// output; for the output ones (interrupt, restart), a twisted beam.
#pragma once

#include "../tests.h"

#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/simulation/static_simulation.h>

namespace SceneTests
{
  using namespace dealii;
  using namespace TissueContact;

  /** A Mooney-Rivlin beam 1 x 0.2 x 0.2 of 2 500 tetrahedra, clamped at
   * x = 0, its far end twisted by 120 degrees in increments from 1/8
   * (growing), writing to @p directory with base name "beam". */
  inline std::string
  twisted_beam(const std::string &directory)
  {
    return R"(
subsection Mesh
  set Source           = box
  set Box upper corner = 1, 0.2, 0.2
  set Box subdivisions = 50, 5, 2
end
subsection Bodies
  subsection Body 0
    set Model = Mooney-Rivlin
    set C1    = 5
    set C2    = 1
    set a     = 50
  end
end
subsection Boundary conditions
  set Number of Dirichlet conditions = 2
  subsection Dirichlet 0
    set Boundary id = 0
  end
  subsection Dirichlet 1
    set Boundary id     = 1
    set Rotation axis   = 1, 0, 0
    set Rotation center = 0, 0.1, 0.1
    set Rotation angle  = 120
  end
end
subsection Load stepping
  set Initial increment = 0.125
end
subsection Output
  set Directory        = )" +
           directory + R"(
  set Base name        = beam
  set Print timing     = false
end
)";
  }

  /** Solve @p sim quietly into @p statistics. If it stops, log "@p what
   * stopped: <the message>" and return false. */
  inline bool
  solve_or_log(StaticSimulation  &sim,
               SolveStatistics   &statistics,
               const std::string &what)
  {
    try
      {
        statistics = sim.solve_quietly();
        return true;
      }
    catch (const std::exception &e)
      {
        deallog << what << " stopped: " << TissueContact::error_message(e)
                << std::endl;
        return false;
      }
  }

  /** Log whether the solve of @p what stayed within @p max_cutbacks
   * cut-backs and @p max_newton Newton iterations; print the exact figures
   * to the console only. These scenes' increments and iterations are not a
   * property of the code but of its rounding: the same prm gave 30 and 39
   * increments (0 and 4 cut back) for the coarse knee and 77 and 85 for
   * the apple snake with two builds that differ only at rounding level
   * (doc/users/knee.md), so the log holds the bounds, not the counts. */
  inline void
  log_effort(const SolveStatistics &statistics,
             const std::string     &what,
             const unsigned int     max_cutbacks,
             const unsigned int     max_newton)
  {
    std::cout << what << ": " << statistics.increments << " increments ("
              << statistics.cutbacks << " cut back), "
              << statistics.newton_iterations << " Newton iterations"
              << std::endl;
    deallog << what << ": at most " << max_cutbacks << " cut-backs: "
            << (statistics.cutbacks <= max_cutbacks ? "yes" : "no")
            << ", fewer than " << max_newton << " Newton iterations: "
            << (statistics.newton_iterations < max_newton ? "yes" : "no")
            << std::endl;
  }

  /** Log whether @p penetration (a fraction of the local element size) is
   * below 0.1; print its value to the console only (it varies with the
   * rounding like the iteration counts). */
  inline void
  log_penetration(const double penetration)
  {
    std::cout << "largest penetration / local element size " << penetration
              << std::endl;
    deallog << "largest penetration below 0.1 of the local element size: "
            << (penetration < 0.1 ? "yes" : "no") << std::endl;
  }
} // namespace SceneTests
