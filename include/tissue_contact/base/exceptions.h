#pragma once

#include <exception>
#include <stdexcept>
#include <string>

namespace TissueContact
{
  /**
   * The user-facing text of an exception on one line: for a deal.II
   * exception its "additional information" (the ExcMessage text, or the
   * ParameterHandler's description naming the file, line and entry), for
   * any other exception what(). Used wherever an error is reported to the
   * user or wrapped with more context.
   */
  std::string
  error_message(const std::exception &e);

  /**
   * The one way a nonlinear solve reports that it failed: Newton (no
   * convergence, an inverted element, a non-finite residual, a line search
   * without an admissible step), KINSOL, IDA, an implicit time step and the
   * explicit scheme's blow-up check throw it with the reason as what().
   * Load cut-back (Solvers::IncrementalNewtonSolver::solve()) and time-step
   * cut-back (Dynamics::TimeIntegrator::step()) catch it and retry with a
   * smaller increment or step; when they give up they throw it again with
   * the load factor or time and the last reason. Anything else thrown
   * (a bad parameter, a broken mesh) is not a failed solve and is never
   * retried.
   */
  class SolveFailed : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };
} // namespace TissueContact
