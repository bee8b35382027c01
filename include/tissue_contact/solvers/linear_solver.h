#pragma once

#include <tissue_contact/base/nonzero_matrix.h>
#include <tissue_contact/solvers/amg_preconditioner.h>
#include <tissue_contact/solvers/cholesky_factorization.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <memory>
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
     * - "direct": sparse Cholesky by CHOLMOD where the tangent is
     *   symmetric positive definite (CholeskyFactorization; LU by UMFPACK
     *   where it is not), or sparse LU by UMFPACK or by MUMPS (through
     *   Trilinos Amesos; multifrontal), as the entry "Direct solver" says;
     * - "GMRES+AMG": GMRES preconditioned by Trilinos ML aggregation
     *   algebraic multigrid (plain or smoothed aggregation) with the three
     *   translations, or the six rigid-body modes (translations and
     *   rotations), as its near-null space; ML builds the hierarchy, the
     *   cycle runs on deal.II's threads (AMGPreconditioner).
     * Reaching the iteration cap is not an error (inexact Newton); a
     * non-finite solution is.
     */
    class LinearSolver
    {
    public:
      /** Entries of the prm subsection "Linear solver". */
      struct Parameters
      {
        /** "automatic" (resolved(): direct below automatic_limit unknowns,
         * GMRES+AMG from there), "direct", "GMRES+AMG" or "GMRES+Jacobi". */
        std::string  type               = "automatic";
        std::string  direct_solver      = "Cholesky";
        double       relative_tolerance = 0.1;
        unsigned int max_iterations     = 1000;
        /** Krylov vectors GMRES keeps before it restarts; 0: chosen by
         * the preconditioner (restart()). */
        unsigned int gmres_restart = 0;
        /** GMRES's restart with the preconditioner of @p type
         * ("GMRES+AMG" or "GMRES+Jacobi"): gmres_restart, or if that is 0
         * the fastest measured (doc/theory/04-solver.md sec. 4.5.2): 150
         * with AMG, whose iterations cost several products, so that a
         * longer basis pays for its orthogonalization, and 50 with Jacobi,
         * whose iterations cost one. */
        unsigned int
        restart(const std::string &type) const
        {
          return gmres_restart > 0   ? gmres_restart :
                 type == "GMRES+AMG" ? 150 :
                                       50;
        }
        bool amg_rotations = false;
        /** "plain", "smoothed" or "automatic" aggregation
         * (AMGPreconditioner; aggregation()). */
        std::string amg_aggregation = "automatic";
        /** "fixed" (relative_tolerance) or "Eisenstat-Walker". */
        std::string forcing_term = "fixed";
        /** Keep the AMG hierarchy from one solve to the next. */
        bool reuse_preconditioner = false;

        /** The aggregation AMG uses: amg_aggregation, or for "automatic"
         * plain where the hierarchy is kept (reuse_preconditioner, as
         * Type = automatic sets it), whose operators are then refreshed
         * for each matrix, and smoothed where each solve builds its own:
         * measured in doc/theory/04-solver.md sec. 4.5.2. */
        std::string
        aggregation() const
        {
          return amg_aggregation != "automatic" ? amg_aggregation :
                 reuse_preconditioner           ? "plain" :
                                                  "smoothed";
        }

        /** With Type = GMRES+AMG (chosen or automatic): the Newton steps of
         * the energy line search by conjugate gradients with AMG, which
         * tell a tangent that is not positive definite; it is then shifted
         * (doc/theory/04-solver.md sec. 4.3.2). False: GMRES for them as
         * for every other solve. */
        bool definite_steps = true;
        /** Solve directly where GMRES+AMG does not converge (set by
         * resolved() for Type = automatic; LinearSolver::solve()). */
        bool direct_fallback = false;

        /** Type = automatic chooses the direct solver below this many
         * unknowns and GMRES+AMG from it on: the crossover measured on a
         * P1 cantilever without contact lies between 7 000 and 16 000
         * unknowns (doc/users/choosing.md), and contact couplings make
         * the factorization dearer still. */
        static constexpr types::global_dof_index automatic_limit = 10000;

        /** These parameters with Type = automatic replaced by the solver
         * it chooses for @p n_dofs unknowns: the direct solver, or GMRES+AMG
         * with the settings its crossover was measured with (the
         * Eisenstat-Walker forcing term, the hierarchy reused, the six
         * rigid-body modes, the direct solver where GMRES does not
         * converge). With AMG's own defaults (a fixed tolerance of
         * 0.1, a new three-mode hierarchy per solve) the falling rods
         * (25 704 unknowns, 30 steps) took 47 s against the direct
         * solver's 27 s; with these, 21 s. */
        /**
         * ... and for a tangent with @p widening times the entries of the
         * element couplings alone (wider couplings: the vertex volume
         * term's, contact pairs'), the limit divided by @p widening squared:
         * a factorization's fill grows with the couplings' reach, where
         * more entries per row from a higher degree do not move the
         * crossover. Measured (doc/users/choosing.md): P1 and P2 cross over
         * at about 7 800 and 8 800 unknowns with 34 and 68 entries per row;
         * P1 with the vertex term, 2.5 times the element couplings'
         * entries, between 1 200 and 2 475 (10 000 / 2.5^2 = 1 600).
         */
        Parameters
        resolved(const types::global_dof_index n_dofs,
                 const double                  widening = 1.) const
        {
          Parameters p = *this;
          if (p.type == "automatic")
            {
              const double w = std::max(widening, 1.);
              p.type =
                n_dofs * w * w < automatic_limit ? "direct" : "GMRES+AMG";
              if (p.type == "GMRES+AMG")
                {
                  p.forcing_term         = "Eisenstat-Walker";
                  p.reuse_preconditioner = true;
                  p.amg_rotations        = true;
                  p.direct_fallback      = true;
                }
            }
          return p;
        }

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

      /** With Type = automatic the solver is chosen by the size of each
       * matrix solved (callers that pass a near-null space resolve it
       * first, Parameters::resolved(), to know whether AMG needs one);
       * @p near_null_space: the vectors AMG's coarse spaces must
       * represent (NonlinearProblem::near_null_space(); empty: one
       * constant vector). */
      LinearSolver(const Parameters                  &parameters,
                   const std::vector<Vector<double>> &near_null_space = {});

      /** Solve @f$K x = b@f$ to the relative residual @p
       * relative_tolerance (iterative solvers; negative: the prm's);
       * returns the number of iterations (1 for the direct solver). Throws
       * if the result is not finite. With Reuse preconditioner, the AMG
       * hierarchy of an earlier solve is kept until the iterations it
       * has cost beyond its first solve's rate (iterations per decade of
       * residual) add up to setup_cost, within a solve too, where GMRES
       * then goes on from the iterate reached with a new one; a fresh
       * hierarchy with which GMRES reaches its cap is not kept. The
       * hierarchy keeps its own copy of the matrix it was built from, so
       * it stays a valid preconditioner when @p K is a later
       * tangent, also one with more contact couplings in its pattern: only
       * the convergence rate decides when it is replaced. The iterative
       * solvers start from @p x if @p from_x (a nearby system's solution:
       * the residual is still measured against |b|, and 0 iterations are
       * returned if @p x already meets it), else from zero; the direct
       * solver ignores it. */
      unsigned int
      solve(const SparseMatrix<double> &K,
            Vector<double>             &x,
            const Vector<double>       &b,
            const double                relative_tolerance = -1.,
            const bool                  from_x             = false) const;


      /**
       * The relative tolerance of the linear solve of Newton iteration k
       * (doc/theory/04-solver.md, sec. 4.5.1): with the fixed forcing term,
       * Relative tolerance; with Eisenstat-Walker (1996, choice 2,
       * @f$\gamma = 0.9@f$, @f$\alpha = 2@f$)
       * @f$\eta_k = \gamma (|R_k|/|R_{k-1}|)^\alpha@f$, kept above
       * @f$\gamma\eta_{k-1}^\alpha@f$ when that exceeds 0.1, above
       * @f$\tfrac12 \tau/|R_k|@f$ (no solve much beyond the Newton
       * tolerance @f$\tau@f$) and below @f$\eta_{max}@f$ = Relative
       * tolerance. @p r_previous = 0: the first iteration,
       * @f$\eta_0 = \eta_{max}@f$.
       */
      double
      forcing(const double r,
              const double r_previous,
              const double eta_previous,
              const double tolerance) const;

      /** Whether solves of an @p n_dofs x @p n_dofs matrix see only its
       * nonzeros: GMRES multiplies with them, AMG is built from them and
       * the direct fallback of Type = automatic factorizes them. Entries
       * stored but zero then change no bit of a solution; the direct
       * solver chosen as such factorizes every stored entry. */
      bool
      sees_nonzeros_only(const types::global_dof_index n_dofs) const
      {
        return parameters.resolved(n_dofs).type != "direct";
      }

      /** The solves of Type = automatic that fell back to the direct
       * solver, since construction. */
      unsigned int
      direct_fallbacks() const
      {
        return n_direct_fallbacks;
      }

      /** The solves of Direct solver = Cholesky factorized by LU instead:
       * those whose tangent was not symmetric positive definite, and
       * those after such a one that did not try (solve_direct()), since
       * construction. */
      unsigned int
      cholesky_fallbacks() const
      {
        return n_cholesky_fallbacks;
      }

      /** Whether solve() factorizes an @p n_dofs x @p n_dofs tangent by
       * Cholesky where it can (Type = direct, or automatic choosing it, and
       * Direct solver = Cholesky): then solve_definite() tests it. */
      bool
      factorizes_by_cholesky(const types::global_dof_index n_dofs) const
      {
        const Parameters p = parameters.resolved(n_dofs);
        return p.type == "direct" && p.direct_solver == "Cholesky";
      }

      /** What solve_definite() found. */
      enum class Definiteness
      {
        positive_definite,
        not_positive_definite,
        not_symmetric
      };

      /** Solve @f$K x = b@f$ if @p K is symmetric positive definite, else
       * leave @p x undefined and say which test failed: the Newton
       * solver's definite steps (doc/theory/04-solver.md sec. 4.3.1). By
       * the Cholesky factorization (factorizes_by_cholesky(); independent
       * of solve()'s back-off, and not counted in cholesky_fallbacks()),
       * or by conjugate gradients with the AMG preconditioner to
       * @p relative_tolerance (of |b|), which stop at the first search
       * direction p with p.Kp not positive (then kept in @p direction,
       * else @p direction is left empty) or preconditioned residual r.z
       * not positive. @p iterations: the CG iterations spent, or 1 for a
       * factorization that was solved with. @p test_symmetry: false where
       * the caller knows K is symmetric (a shift of the diagonal of a
       * matrix that was). */
      Definiteness
      solve_definite(const SparseMatrix<double> &K,
                     Vector<double>             &x,
                     const Vector<double>       &b,
                     const double                relative_tolerance,
                     unsigned int               &iterations,
                     Vector<double>             &direction,
                     const bool                  test_symmetry = true) const;

      /** Whether solve_definite() can tell if an @p n_dofs x @p n_dofs
       * tangent is positive definite: by the Cholesky factorization
       * (factorizes_by_cholesky()), or by conjugate gradients with AMG
       * (Type = GMRES+AMG, or automatic choosing it, with Definite steps =
       * true). */
      bool
      tests_definiteness(const types::global_dof_index n_dofs) const
      {
        const Parameters p = parameters.resolved(n_dofs);
        return factorizes_by_cholesky(n_dofs) ||
               (p.type == "GMRES+AMG" && p.definite_steps);
      }

      const Parameters parameters;

    private:
      /** Sparse LU (UMFPACK or MUMPS) or Cholesky (CHOLMOD, LU where the
       * tangent is not symmetric positive definite), as Direct solver
       * says. */
      void
      solve_direct(const SparseMatrix<double> &K,
                   Vector<double>             &x,
                   const Vector<double>       &b) const;

      /** Solve by the direct solver where GMRES+AMG, chosen by Type =
       * automatic, did not converge with a fresh hierarchy: on the
       * tangent's nonzeros, counted in direct_fallbacks(). */
      void
      solve_direct_fallback(const SparseMatrix<double> &K,
                            Vector<double>             &x,
                            const Vector<double>       &b) const;

      /** The near-null space, mode after mode (ML's layout). */
      std::vector<double> null_space;
      unsigned int        null_space_dimension;

      /** GMRES with AMG from the iterate @p x to the residual @p target
       * (absolute); builds the hierarchy if there is none. With @p
       * stop_on_stagnation (a failure falls back to the direct solver) a
       * fresh hierarchy's solve stops when its restart cycles stagnate
       * (StagnationControl). */
      unsigned int
      solve_amg(const SparseMatrix<double> &K,
                Vector<double>             &x,
                const Vector<double>       &b,
                const double                target,
                const bool                  stop_on_stagnation,
                bool                       &converged,
                bool                       *negative_curvature = nullptr,
                Vector<double>             *direction          = nullptr) const;

      /** @p K's nonzeros copied into the buffer that the AMG hierarchy's
       * accepted operators do not hold, which becomes the current one
       * (a refreshed hierarchy's finest level shares it: one copy per
       * solve instead of two; doc/theory/04-solver.md sec. 4.5.1). */
      void
      copy_nonzeros_of(const SparseMatrix<double> &K) const;

      /** Two buffers for the tangent's nonzeros, GMRES's and CG's
       * operator (the same products at 40 % of the cost on the full knee,
       * 0.16 against 0.41 ms), and the current one: the last copied. */
      mutable std::array<std::shared_ptr<NonzeroMatrix>, 2> nonzero_buffers{
        {std::make_shared<NonzeroMatrix>(), std::make_shared<NonzeroMatrix>()}};
      mutable std::shared_ptr<NonzeroMatrix> nonzeros = nonzero_buffers[0];

      /** The hierarchy (with its copy of the matrix it was built from). */
      mutable std::unique_ptr<AMGPreconditioner> amg;
      /** Iterations per decade of residual of the first solve with the
       * current hierarchy that iterated (negative: none has yet). */
      mutable double fresh_rate = -1.;
      /** Iterations the current hierarchy has cost beyond fresh_rate per
       * decade, summed over its solves. */
      mutable double excess = 0.;
      /** A hierarchy's setup in GMRES iterations: 0.21 s against 4.1 ms
       * per iteration on the full knee, two threads, when it was set; 70 ms
       * against 2.15 ms (33) with the cycle on the threads, where 33 gained
       * nothing beyond the Newton paths' spread (doc/theory/04-solver.md
       * sec. 4.5.1). */
      static constexpr double setup_cost         = 50.;
      mutable unsigned int    n_direct_fallbacks = 0;
      /** Direct solver = Cholesky: the factorization, whose symbolic
       * analysis serves the next tangents of the same pattern. */
      mutable std::unique_ptr<CholeskyFactorization> cholesky;
      mutable unsigned int                           n_cholesky_fallbacks = 0;
      /** Solves that go to the LU without a Cholesky attempt, and how many
       * the next failure makes skip (1, doubled by each failure in a row up
       * to 8, cleared by a success). */
      mutable unsigned int cholesky_skips   = 0;
      mutable unsigned int cholesky_backoff = 0;
    };
  } // namespace Solvers
} // namespace TissueContact
