#pragma once

#include <tissue_contact/base/compressed_rows.h>
#include <tissue_contact/base/nonzero_matrix.h>

#include <deal.II/lac/diagonal_matrix.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <Amesos_BaseSolver.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_Map.h>
#include <Epetra_MpiComm.h>

#include <array>
#include <functional>
#include <memory>
#include <vector>

namespace TissueContact
{
  namespace Solvers
  {
    using namespace dealii;

    /**
     * One V-cycle of aggregation algebraic multigrid whose every level
     * runs on deal.II's threads (doc/theory/04-solver.md sec. 4.5.2).
     *
     * Trilinos ML builds the hierarchy (aggregates, prolongators and the
     * Galerkin coarse operators) from a copy of the matrix @f$A@f$ without
     * its stored zeros (most of a contact tangent's entries); the cycle
     * then runs on the project's copies of its operators, read out of ML
     * once per hierarchy, because ML's own cycle is serial here (Epetra
     * without OpenMP). On level @f$l@f$, with @f$A_l@f$ its operator
     * (@f$A_0 = A@f$), @f$P_l@f$ the prolongator from level @f$l@f$ to
     * level @f$l-1@f$, @f$R_l = P_l^T@f$ (ML's restriction), and
     * @f$S_l@f$ deal.II's Chebyshev smoother (degree 2, Jacobi-scaled, as
     * ML's own), the correction of level @f$l-1@f$ by the levels below it
     * is @f$C_l r = P_l\,V_l(R_l r)@f$, where on the coarsest level
     * @f$V_l = A_l^{-1}@f$ (a sparse direct factorization, as ML's KLU)
     * and above it
     * @f[
     *   x_1 = S_l\,b, \qquad x_2 = x_1 + C_{l+1}(b - A_l x_1), \qquad
     *   V_l b = x_2 + S_l\,(b - A_l x_2);
     * @f]
     * the preconditioner is @f$V_0@f$. This is the V-cycle ML runs, with
     * every product, smoothing step and transfer on the threads. The
     * operator is fixed between calls of initialize(), refresh() and
     * restore() (it uses the copies, not later matrices), so a Krylov
     * method may keep it across systems.
     */
    class AMGPreconditioner
    {
    public:
      /** Build the hierarchy of @p A (copied without its stored zeros)
       * with the project's ML settings (aggregation threshold 1e-4, the
       * elliptic defaults) and the near-null space @p null_space,
       * @p null_space_dimension vectors of A.m() entries one after the
       * other (none: ML's default), and the smoothers of its levels. With
       * @p smoothed_aggregation the prolongators are the tentative ones
       * smoothed by damped Jacobi (ML's default, damping factor 4/3);
       * without, the tentative ones as they are (plain aggregation: sparser
       * coarse operators, a cheaper setup and cycle, more iterations;
       * doc/theory/04-solver.md sec. 4.5.2). */
      void
      initialize(const SparseMatrix<double> &A,
                 const std::vector<double>  &null_space,
                 const unsigned int          null_space_dimension,
                 const bool                  smoothed_aggregation);

      /** The hierarchy for the matrix @p A (of the size it was built
       * for), on the aggregates and transfers it was built with: every
       * level's operator anew, @f$A_l = R_l A_{l-1} P_l@f$ from
       * @f$A_0 = A@f$ without its stored zeros, and with it the smoothers
       * and the coarsest factorization (doc/theory/04-solver.md sec.
       * 4.5.1). The operators of the last accept() are kept beside them.
       * With @p A_nonzeros (A's nonzeros as the caller copied them, the
       * Krylov method's operator) the finest level shares that copy instead
       * of copying A again; the caller must not change it while it is
       * accepted_finest(). */
      void
      refresh(const SparseMatrix<double>                 &A,
              const std::shared_ptr<const NonzeroMatrix> &A_nonzeros = {});

      /** The finest level's operator of the last accept(), kept through
       * the next refresh() (null: none). */
      const NonzeroMatrix *
      accepted_finest() const;

      /** The current operators are those of a matrix the Krylov method
       * solved without a refusal: kept through later refresh() calls until
       * the next accept(). */
      void
      accept();

      /** Go back to the operators of the last accept(), if they are not
       * the current ones; returns whether it did. */
      bool
      restore();

      /** @p x = the V-cycle applied to @p b. */
      void
      vmult(Vector<double> &x, const Vector<double> &b) const;

      /** Rows of the matrix it was built from. */
      types::global_dof_index
      m() const
      {
        return n_rows;
      }

      /** Levels of the hierarchy, the finest included. */
      unsigned int
      n_levels() const
      {
        return grids.size();
      }

    private:
      using Smoother = PreconditionChebyshev<NonzeroMatrix,
                                             Vector<double>,
                                             DiagonalMatrix<Vector<double>>>;

      /** Entries in sixes: item u's entries index[start[u]] ...
       * index[start[u + 1] - 1], each with six values. Either R's rows six
       * at a time (an item a unit of six rows, an index one of their
       * columns, the values the six rows' there), or a matrix's rows whose
       * columns come in blocks of six (an item a row, an index a block
       * 6 K ... 6 K + 5, the values the row's in those columns, zero where
       * it has none). */
      struct Sixes
      {
        std::vector<std::size_t>             start;
        std::vector<types::global_dof_index> index;
        std::vector<std::array<double, 6>>   value;
      };

      /** A level's transfers from and to the level above (none on the
       * finest), and its vectors: right-hand side, iterate, residual and
       * the correction from below. */
      struct Grid
      {
        /** P, its rows in blocks of six columns (an aggregate's six coarse
         * unknowns), and R, its rows six at a time, their columns merged:
         * the cycle's transfers and the Galerkin products' factors of
         * refresh(), both made once per hierarchy */
        Sixes                  P_blocks, R_units;
        mutable Vector<double> b, x, residual, correction;
      };

      /** A level's operator: its nonzeros in groups of three rows
       * (base/nonzero_matrix.h) and its smoother, or on the coarsest level
       * its sparse LU factorization by KLU (Amesos), ML's own coarse
       * solver. */
      struct Level
      {
        /** its own, or on the finest level one shared with the caller */
        std::shared_ptr<const NonzeroMatrix>  A;
        Smoother                              smoother;
        std::unique_ptr<Epetra_MpiComm>       comm;
        std::unique_ptr<Epetra_Map>           map;
        std::unique_ptr<Epetra_CrsMatrix>     matrix;
        std::unique_ptr<Epetra_LinearProblem> problem;
        std::unique_ptr<Amesos_BaseSolver>    direct;
      };

      using Operators = std::vector<std::unique_ptr<Level>>;

      /** The finest level's operator (@p l = 0) in @p operators from
       * @p matrix: its nonzeros (@p nonzeros if given, else a copy) and
       * smoother, and with a single level its factorization. */
      void
      set_operator(Operators                                  &operators,
                   const unsigned int                          l,
                   const SparseMatrix<double>                 &matrix,
                   const std::shared_ptr<const NonzeroMatrix> &nonzeros = {});

      /** A coarser level's operator (@p l > 0) from @p matrix: its
       * nonzeros and smoother, or on the coarsest level its factorization
       * (no SparseMatrix is built: a refresh of the full knee spent a
       * third of its time building one per level). */
      void
      set_operator(Operators            &operators,
                   const unsigned int    l,
                   const CompressedRows &matrix);

      /** @p level's KLU factorization of the matrix of @p n rows
       * @p make_matrix writes on the map it is given. */
      static void
      factorize(Level                  &level,
                const unsigned int      n,
                const std::function<std::unique_ptr<Epetra_CrsMatrix>(
                  const Epetra_Map &)> &make_matrix);

      /** @p level's smoother of its operator level.A. */
      static void
      set_smoother(Level &level);

      /** @p x = A_l^{-1} @p b on the coarsest level @p level. */
      static void
      solve_coarsest(const Level          &level,
                     Vector<double>       &x,
                     const Vector<double> &b);

      /** @p x = V_l @p b on level @p l. */
      void
      cycle(const unsigned int    l,
            Vector<double>       &x,
            const Vector<double> &b) const;

      std::vector<std::unique_ptr<Grid>> grids;
      /** Two sets of operators: the current one, and the last accepted
       * one if it is the other (accepted < 0: none). */
      std::array<Operators, 2> operators;
      unsigned int             current  = 0;
      int                      accepted = -1;
      /** Rows of the finest level. */
      types::global_dof_index n_rows = 0;
    };
  } // namespace Solvers
} // namespace TissueContact
