// Shared by the showcase scene tests (the knee, the snakes): solve a scene
// quietly, and log where it stopped instead of failing without output.
#pragma once

#include "../tests.h"

#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/simulation/static_simulation.h>

namespace SceneTests
{
  using namespace dealii;
  using namespace TissueContact;

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
} // namespace SceneTests
