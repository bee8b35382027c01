#pragma once

#include <tissue_contact/solvers/linear_solver.h>
#include <tissue_contact/solvers/nonlinear_problem.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/vector.h>
#include <deal.II/sundials/kinsol.h>

#include <string>

namespace TissueContact
{
  namespace Solvers
  {
    using namespace dealii;

    /**
     * SUNDIALS' KINSOL as the alternative to the project's Newton loop for
     * one nonlinear solve (a load increment, an implicit time step),
     * doc/theory/04-solver.md, sec. 4.6. The unknowns are all DoFs: the
     * residual is R on the free DoFs and @f$u_i - \bar u_i@f$ on the
     * prescribed ones; the Jacobian is the assembled tangent with the
     * prescribed rows replaced by identity rows, factored (direct) or
     * solved with the project's linear solver in setup_jacobian() /
     * solve_with_jacobian().
     */
    class KinsolSolver
    {
    public:
      /** Entries of the prm subsection "Newton/KINSOL": the settings of
       * SUNDIALS::KINSOL::AdditionalData the project uses, documented. */
      struct Parameters
      {
        SUNDIALS::KINSOL<Vector<double>>::AdditionalData data;

        /** KINSOL's defaults, but plain Newton steps (the project's
         * tangent is exact). */
        Parameters()
        {
          data.strategy =
            SUNDIALS::KINSOL<Vector<double>>::AdditionalData::newton;
        }

        /** Enter "KINSOL" and bind its entries to @p data. */
        void
        declare_parameters(ParameterHandler &prm);
      };

      KinsolSolver(const Parameters               &parameters,
                   const LinearSolver::Parameters &linear_solver);

      /**
       * Solve @p problem at @p load_factor from the initial guess @p u.
       * @p tolerance: the largest entry of the residual on the free DoFs at
       * convergence (used unless the prm sets a function tolerance).
       * @p iterations gets the number of nonlinear iterations. Throws
       * SolveFailed with KINSOL's reason if it does not converge.
       */
      void
      solve(NonlinearProblem &problem,
            Vector<double>   &u,
            const double      load_factor,
            const double      tolerance,
            unsigned int     &iterations) const;

    private:
      const Parameters               parameters;
      const LinearSolver::Parameters linear_solver;
    };
  } // namespace Solvers
} // namespace TissueContact
