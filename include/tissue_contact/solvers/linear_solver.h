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
     * - "direct": sparse LU, by UMFPACK or by MUMPS (through Trilinos
     *   Amesos; multifrontal, faster on large 3D meshes, see the entry
     *   "Direct solver");
     * - "GMRES+AMG": GMRES preconditioned by Trilinos ML smoothed-aggregation
     *   algebraic multigrid with the three translations, or the six
     *   rigid-body modes (translations and rotations), as its near-null
     *   space.
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
        std::string  direct_solver      = "UMFPACK";
        double       relative_tolerance = 0.1;
        unsigned int max_iterations     = 1000;
        bool         amg_rotations      = false;

        /** Whether the solver uses a near-null space (GMRES+AMG): the
         * others need none, so none is computed for them. */
        bool
        uses_near_null_space() const
        {
          return type == "GMRES+AMG";
        }

        /** Enter "Linear solver" and bind its entries to this object. */
        void
        declare_parameters(ParameterHandler &prm);
      };

      /** @p near_null_space: the vectors AMG's coarse spaces must
       * represent (NonlinearProblem::near_null_space(); empty: one
       * constant vector). */
      LinearSolver(const Parameters                  &parameters,
                   const std::vector<Vector<double>> &near_null_space = {});

      /** Solve @f$K x = b@f$; returns the number of iterations (1 for the
       * direct solver). Throws if the result is not finite. */
      unsigned int
      solve(const SparseMatrix<double> &K,
            Vector<double>             &x,
            const Vector<double>       &b) const;

      const Parameters parameters;

    private:
      /** The near-null space, mode after mode (ML's layout). */
      std::vector<double> null_space;
      unsigned int        null_space_dimension;
    };
  } // namespace Solvers
} // namespace TissueContact
