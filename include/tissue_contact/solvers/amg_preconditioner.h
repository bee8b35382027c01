#pragma once

#include <tissue_contact/base/nonzero_matrix.h>

#include <deal.II/lac/diagonal_matrix.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace TissueContact
{
  namespace Solvers
  {
    using namespace dealii;

    /**
     * One V-cycle of aggregation algebraic multigrid whose finest level
     * runs on deal.II's threads (doc/theory/04-solver.md sec. 4.5.2).
     *
     * Trilinos ML builds the hierarchy (aggregates, prolongators, coarse
     * operators and their Chebyshev smoothers) from a copy of the matrix
     * @f$A@f$ without its stored zeros (most of a contact tangent's
     * entries), but is told to do nothing on the finest level; there
     * deal.II's Chebyshev smoother @f$S@f$ (degree 2, Jacobi-scaled, as
     * ML's own) and the residual run on the project's copy of the nonzeros
     * (NonzeroMatrix), whose products use the threads. With @f$C@f$ the coarse
     * correction ML applies
     * (@f$C r = P\,M_c^{-1} R\,r@f$, the cycle below the finest level):
     * @f[
     *   x_1 = S\,b, \qquad x_2 = x_1 + C\,(b - A x_1), \qquad
     *   x = x_2 + S\,(b - A x_2),
     * @f]
     * the same cycle ML runs with its own finest-level smoother, which is
     * serial here (Epetra without OpenMP). The operator is fixed between
     * initialize() calls (it uses the copy, not later matrices), so a
     * Krylov method may keep it across systems.
     */
    class AMGPreconditioner
    {
    public:
      /** Build the hierarchy of @p A (copied without its stored zeros)
       * with the project's ML settings (Chebyshev, 2 sweeps, aggregation
       * threshold 1e-4, the elliptic defaults) and the near-null space @p
       * null_space, @p null_space_dimension vectors of A.m() entries one
       * after the other (none: ML's default). With @p smoothed_aggregation
       * the prolongators are the tentative ones smoothed by damped Jacobi
       * (ML's default, damping factor 4/3); without, the tentative ones as
       * they are (plain aggregation: sparser coarse operators, a cheaper
       * setup and cycle, more iterations; doc/theory/04-solver.md
       * sec. 4.5.2). */
      void
      initialize(const SparseMatrix<double> &A,
                 const std::vector<double>  &null_space,
                 const unsigned int          null_space_dimension,
                 const bool                  smoothed_aggregation);

      /** @p x = the V-cycle applied to @p b. */
      void
      vmult(Vector<double> &x, const Vector<double> &b) const;

      /** Rows of the matrix it was built from. */
      types::global_dof_index
      m() const
      {
        return finest.m();
      }

    private:
      /** The finest level's operator: the nonzeros of A in groups of three
       * rows, whose products are those of A to the last bit in about two
       * thirds of the time (0.27-0.29 against 0.41-0.44 ms on a tangent of
       * the full knee, one thread; base/nonzero_matrix.h). */
      NonzeroMatrix finest;
      /** ML's copy of the matrix (its hierarchy keeps a reference). */
      TrilinosWrappers::SparseMatrix    ml_matrix;
      TrilinosWrappers::PreconditionAMG coarse_levels;
      using Smoother = PreconditionChebyshev<NonzeroMatrix,
                                             Vector<double>,
                                             DiagonalMatrix<Vector<double>>>;
      Smoother               smoother;
      mutable Vector<double> residual, correction;
    };
  } // namespace Solvers
} // namespace TissueContact
