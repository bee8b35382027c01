#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <string>
#include <vector>

namespace TissueContact
{
  namespace Solvers
  {
    using namespace dealii;

    /**
     * The linear solver of one Newton step, selectable in the prm:
     * - "GMRES+Jacobi": GMRES with diagonal preconditioning stopped at a
     *   relative residual (0.1 by default) or an iteration cap, the inexact
     *   Newton method of dissertation sec. 4.7.3;
     * - "direct": sparse LU (UMFPACK);
     * - "GMRES+AMG": GMRES preconditioned by Trilinos ML smoothed-aggregation
     *   algebraic multigrid with the three displacement components as
     *   near-null-space modes.
     * Reaching the iteration cap is not an error (inexact Newton); a
     * non-finite solution is.
     */
    class LinearSolver
    {
    public:
      /** Entries of the prm subsection "Linear solver". */
      struct Parameters
      {
        std::string  type               = "direct";
        double       relative_tolerance = 0.1;
        unsigned int max_iterations     = 1000;

        /** Enter "Linear solver" and bind its entries to this object. */
        void
        declare_parameters(ParameterHandler &prm);
      };

      /** @p constant_modes: per component, which DoFs belong to it (for
       * AMG; may be empty). */
      LinearSolver(const Parameters                     &parameters,
                   const std::vector<std::vector<bool>> &constant_modes = {});

      /** Solve @f$K x = b@f$; returns the number of iterations (1 for the
       * direct solver). Throws if the result is not finite. */
      unsigned int
      solve(const SparseMatrix<double> &K,
            Vector<double>             &x,
            const Vector<double>       &b) const;

      const Parameters parameters;

    private:
      const std::vector<std::vector<bool>> constant_modes;
    };
  } // namespace Solvers
} // namespace TissueContact
