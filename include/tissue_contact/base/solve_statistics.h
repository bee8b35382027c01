#pragma once

#include <string>

namespace TissueContact
{
  /** One Newton iteration, as shown on screen and in the CSV log
   * (Output::ConvergenceLog). */
  struct IterationInfo
  {
    unsigned int increment         = 0;
    double       load_factor       = 0.;
    unsigned int iteration         = 0;
    double       residual_norm     = 0.; // |R| on the free DoFs
    double       update_norm       = 0.; // |s du|
    double       step_length       = 1.; // line-search factor s
    unsigned int linear_iterations = 0;
    /** Converged because the Newton correction can no longer change the
     * displacement in floating point, with |R| at its rounding floor above
     * the tolerance (doc/theory/04-solver.md sec. 4.2.1). */
    bool at_rounding = false;
  };

  /** Summary of a whole solve: converged load increments, cut-backs, the
   * Newton and linear iterations they took, the linear solves repeated
   * with a shifted tangent because the Newton step did not descend, and
   * the augmented-Lagrangian updates. */
  struct SolveStatistics
  {
    unsigned int increments        = 0;
    unsigned int cutbacks          = 0;
    unsigned int newton_iterations = 0;
    unsigned int linear_iterations = 0;
    unsigned int tangent_shifts    = 0;
    /** Increments that converged to rounding (IterationInfo::at_rounding). */
    unsigned int rounding_convergences = 0;
    /** Augmented-Lagrangian updates, each followed by another solve. */
    unsigned int multiplier_updates = 0;
    /** Linear solves of Type = automatic that GMRES+AMG did not converge
     * and the direct solver did (LinearSolver::solve()). */
    unsigned int direct_fallbacks = 0;
    /** Linear solves of Direct solver = Cholesky made by LU instead (a
     * tangent not symmetric positive definite, or one of the solves after
     * such a one; LinearSolver::cholesky_fallbacks()). */
    unsigned int cholesky_fallbacks = 0;
  };

  /** The run summary's clause for @p n linear solves made by LU instead of
   * Cholesky (SolveStatistics::cholesky_fallbacks), empty for none. */
  inline std::string
  cholesky_fallback_summary(const unsigned int n)
  {
    return n == 0 ? std::string() :
                    ", " + std::to_string(n) +
                      " linear solves by LU instead of Cholesky (tangents not "
                      "symmetric positive definite, and the solves right "
                      "after them)";
  }
} // namespace TissueContact
