#pragma once

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>

namespace TissueContact
{
  namespace Solvers
  {
    using namespace dealii;

    /** Whether @p K is symmetric: |K v - K^T v| <= 1e-12 (|K v| + |K^T v|)
     * for a fixed vector v of pseudo-random entries in [-1, 1]. */
    bool
    is_symmetric(const SparseMatrix<double> &K);


    /**
     * The sparse Cholesky factorization @f$K = LL^T@f$ of a symmetric
     * positive definite tangent by CHOLMOD (SuiteSparse's; simplicial, or
     * supernodal with the dense blocks in BLAS from 150 flops per entry of
     * the factor on), its symbolic analysis kept for the next tangents of
     * the same sparsity pattern (doc/theory/04-solver.md sec. 4.5.3).
     *
     * A hyperelastic tangent with penalty contact is the Hessian of a
     * potential, so it is symmetric; it is positive definite at a stable
     * equilibrium and wherever the quasi-viscosity or a mass term
     * dominates, and may be
     * indefinite elsewhere. factorize() therefore checks both and says
     * whether it succeeded; the caller factorizes by LU where it did not.
     * Symmetry: @f$|Kv - K^Tv| \le 10^{-12}(|Kv| + |K^Tv|)@f$ for a fixed
     * vector @f$v@f$ of pseudo-random entries (a tangent assembled as
     * symmetric differs from its transpose by rounding, about
     * @f$10^{-16}@f$; a follower load's tangent by its order). Positive
     * definiteness: the factorization itself, which meets a pivot that is
     * not positive otherwise.
     *
     * CHOLMOD reads the upper triangle of @f$K@f$ (row i, columns
     * @f$j \ge i@f$ of deal.II's rows, which store the diagonal first and
     * the others in order), every stored entry, zeros included, so that
     * the pattern, and with it the analysis (a fill-reducing ordering,
     * METIS or AMD as CHOLMOD finds best, and the supernodes), stays the
     * same while the matrix's pattern does.
     */
    class CholeskyFactorization
    {
    public:
      CholeskyFactorization();
      ~CholeskyFactorization();

      /** Factorize @p K; false (and no usable factor) if @p K is not
       * symmetric or not positive definite. Throws if CHOLMOD runs out
       * of memory. The symbolic analysis of the previous call is reused
       * when @p K has the same pattern. */
      bool
      factorize(const SparseMatrix<double> &K);

      /** @f$x = K^{-1} b@f$ with the factor of the last successful
       * factorize(). */
      void
      solve(Vector<double> &x, const Vector<double> &b) const;

      /** Whether the matrix of the last factorize() call passed the
       * symmetry check (so that a refusal means: not positive definite). */
      bool
      was_symmetric() const;

      /** How many factorize() calls computed a new symbolic analysis. */
      unsigned int
      n_analyses() const;

    private:
      struct Implementation;
      std::unique_ptr<Implementation> implementation;
    };
  } // namespace Solvers
} // namespace TissueContact
