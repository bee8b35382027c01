#pragma once

#include <tissue_contact/base/solve_statistics.h>
#include <tissue_contact/solvers/kinsol_solver.h>
#include <tissue_contact/solvers/linear_solver.h>
#include <tissue_contact/solvers/nonlinear_problem.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <functional>
#include <memory>
#include <string>

namespace TissueContact
{
  namespace Solvers
  {
    /**
     * The static solver of dissertation sec. 4.7 (doc/theory/04-solver.md):
     * - LOOP 1, adaptive incremental loading of the load factor
     *   @f$\lambda: 0\to 1@f$ with a two-point predictor
     *   @f$u^{pred} = u_n + \frac{\lambda_{n+1}-\lambda_n}
     *   {\lambda_n-\lambda_{n-1}}(u_n - u_{n-1})@f$; a failed increment is
     *   halved and retried, an easy one lets the next grow;
     * - LOOP 2, Newton: @f$(K + D/\Delta t_k)\,\delta u = -R@f$ with the
     *   prescribed DoFs set to their remaining gap and the optional
     *   quasi-viscosity @f$D@f$, @f$\Delta t_k = \Delta t\,|R_0|/|R_k|@f$
     *   (it fades as the residual falls; doc/theory/04-solver.md);
     * - LOOP 3, line search: @f$s = 1, \frac12, \frac14, \dots@f$ until no
     *   element is inverted and @f$|R|@f$ decreased.
     * Convergence: the prescribed values are reached and
     * @f$|R_{free}| \le \max(\epsilon_{abs}, \epsilon_{rel} f_{scale})@f$,
     * @f$f_{scale} = \max(|\lambda f^{ext}|, |R_{prescribed}|)@f$ (applied
     * loads or reactions).
     */
    class IncrementalNewtonSolver
    {
    public:
      /** Entries of the prm subsections "Load stepping" and "Newton". */
      struct Parameters
      {
        double       initial_increment   = 0.25;
        double       minimum_increment   = 1e-3;
        double       maximum_increment   = 1.;
        double       growth_factor       = 1.5;
        unsigned int easy_iterations     = 5;
        bool         two_point_predictor = true;

        unsigned int max_iterations     = 25;
        double       residual_tolerance = 1e-8;
        double       absolute_tolerance = 1e-12;
        unsigned int max_halvings       = 20;
        bool         energy_line_search = true;
        /** "Newton" (the project's loop) or "KINSOL" per increment. */
        bool                     use_kinsol = false;
        KinsolSolver::Parameters kinsol;
        bool                     quasi_viscosity     = false;
        double                   viscosity_factor    = 0.1;
        double                   viscosity_time_step = 1.;

        LinearSolver::Parameters linear_solver;

        /** Bind the entries of "Load stepping", "Newton" (with its
         * subsection "KINSOL") and "Linear solver" to this object. */
        void
        declare_parameters(ParameterHandler &prm);
        /** Check what was read. */
        void
        parse_parameters(ParameterHandler &prm);
      };

      explicit IncrementalNewtonSolver(const Parameters &parameters);

      /**
       * Where the load stepping stands between two increments: the last
       * converged load factor and the one before it, with that state (the
       * two-point predictor's), the size of the next increment and the
       * counts so far. Everything solve() needs to continue a run exactly
       * as it would have gone on (a checkpoint holds it).
       */
      struct LoadState
      {
        double          lambda = 0., lambda_prev = 0.;
        double          increment_size = 0.;
        bool            have_previous  = false;
        Vector<double>  u_prev;
        SolveStatistics statistics;
      };

      /** The load state, valid during on_increment (after the increment's
       * size update) and after solve(). */
      const LoadState &
      load_state() const
      {
        return state;
      }

      /** Make the next solve() continue from @p start (with the state u
       * it is given at load factor start.lambda) instead of load factor 0. */
      void
      restart_from(const LoadState &start)
      {
        restart = std::make_unique<LoadState>(start);
      }

      /** Called after every Newton iteration. */
      std::function<void(const IterationInfo &)> on_iteration;
      /** Called after every converged increment with its load factor. */
      std::function<void(unsigned int          increment,
                         double                load_factor,
                         const Vector<double> &u)>
        on_increment;
      /** Called when an increment fails and is cut back. */
      std::function<void(double load_factor, const std::string &reason)>
        on_cutback;

      /**
       * Drive @p problem from @p u (the state at load factor 0) to load
       * factor 1. A failed increment (SolveFailed) is retried without the
       * predictor, then halved; throws SolveFailed naming the load factor
       * and the last reason if the increment falls below the minimum. @p timer, if given, gets
       * the sections "assembly" and "linear solve".
       */
      SolveStatistics
      solve(NonlinearProblem &problem,
            Vector<double>   &u,
            TimerOutput      *timer = nullptr);

    private:
      LoadState                  state;
      std::unique_ptr<LoadState> restart;

    public:
      /**
       * One Newton solve (LOOPs 2 and 3) at a fixed load factor starting
       * from @p u. Throws SolveFailed with the reason if it fails (u is
       * then unspecified).
       */
      void
      newton(NonlinearProblem  &problem,
             Vector<double>    &u,
             const double       load_factor,
             const unsigned int increment,
             SolveStatistics   &statistics,
             TimerOutput       *timer = nullptr);

      /**
       * One nonlinear solve at @p load_factor by the configured solver:
       * newton(), or KINSOL (then on_iteration is not called). Throws
       * SolveFailed with the reason if it fails.
       */
      void
      solve_at(NonlinearProblem  &problem,
               Vector<double>    &u,
               const double       load_factor,
               const unsigned int increment,
               SolveStatistics   &statistics,
               TimerOutput       *timer = nullptr);

      const Parameters parameters;

    private:
      SparseMatrix<double>          K;
      Vector<double>                viscosity;
      std::unique_ptr<LinearSolver> linear_solver;
    };
  } // namespace Solvers
} // namespace TissueContact
