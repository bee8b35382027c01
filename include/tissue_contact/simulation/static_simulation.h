#pragma once

#include <tissue_contact/base/solve_statistics.h>
#include <tissue_contact/simulation/checkpoint.h>
#include <tissue_contact/simulation/problem.h>

#include <functional>
#include <map>
#include <ostream>
#include <string>

namespace TissueContact
{
  using namespace dealii;

  /**
   * The static analysis of a scene, the program's main job: owns the
   * scene's Problem and drives it with the incremental Newton solver from
   * load factor 0 to 1 (doc/theory/04-solver.md), writing the VTU/PVD
   * series, the convergence log, the run summary and a TimerOutput summary.
   */
  class StaticSimulation
  {
  public:
    StaticSimulation(const Scene::SceneParameters &parameters,
                     std::ostream                 &out);

    /** Solve and write output. Throws (after keeping every result already
     * written) if the solve fails. With @p restart, continue the run that
     * wrote that checkpoint (its output files are continued). */
    SolveStatistics
    run(const Checkpoint *restart = nullptr);

    /** Solve without writing any file (for tests); @p on_iteration, if
     * given, sees every Newton iteration. On failure the exception
     * (SolveFailed) propagates and solution() holds the last converged
     * increment. */
    SolveStatistics
    solve_quietly(
      const std::function<void(const IterationInfo &)> &on_iteration = {});

    /** The displacement at the last converged load factor. */
    const Vector<double> &
    solution() const
    {
      return u;
    }

    /** The problem it drives. */
    Problem &
    problem()
    {
      return nonlinear_problem;
    }
    const Problem &
    problem() const
    {
      return nonlinear_problem;
    }

    /** The wall time of every timer section of the last run() (seconds;
     * doc/users/running.md lists them), and "total" (the whole run). */
    const std::map<std::string, double> &
    section_times() const
    {
      return times;
    }

  private:
    std::map<std::string, double> times;
    Problem                       nonlinear_problem;
    Vector<double>                u;
    std::ostream                 &out;
  };
} // namespace TissueContact
