#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/base/nonzero_copy.h>
#include <tissue_contact/solvers/amg_preconditioner.h>
#include <tissue_contact/solvers/linear_solver.h>
#include <tissue_contact/solvers/stagnation_control.h>

#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <cmath>

namespace TissueContact
{
  namespace Solvers
  {
    namespace
    {
      /** @p Operator's products, watched: whether one of them, y = A x,
       * had x.y not positive. */
      template <typename Operator>
      struct CurvatureWatch
      {
        explicit CurvatureWatch(const Operator &A)
          : A(A)
        {}
        void
        vmult(Vector<double> &y, const Vector<double> &x) const
        {
          A.vmult(y, x);
          if (!negative && !(x * y > 0.) && x.linfty_norm() > 0.)
            {
              negative = true;
              if (direction != nullptr)
                *direction = x;
            }
        }
        const Operator &A;
        mutable bool    negative = false;
        /** where to keep the first x with x.y not positive (if not null) */
        Vector<double> *direction = nullptr;
      };


      /** GMRES's settings with the preconditioner of @p type: its restart
       * (LinearSolver::Parameters::restart()) and right preconditioning,
       * so that GMRES minimizes and stops on the true residual |K x - b|,
       * the forcing condition of inexact Newton (doc/theory/04-solver.md
       * sec. 4.5.1); left preconditioning stops on |P^-1 (K x - b)|, which
       * on the full knee fell by 10 while the true residual did not fall
       * at all. */
      SolverGMRES<Vector<double>>::AdditionalData
      gmres_settings(const LinearSolver::Parameters &parameters,
                     const std::string              &type)
      {
        SolverGMRES<Vector<double>>::AdditionalData data;
        data.max_n_tmp_vectors     = parameters.restart(type) + 2;
        data.right_preconditioning = true;
        return data;
      }
    } // namespace


    void
    LinearSolver::Parameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      prm.add_parameter(
        "Type",
        type,
        "Linear solver of each Newton step: automatic (direct below 10 000 "
        "unknowns, GMRES+AMG from there: the crossover measured in "
        "doc/users/choosing.md lies between 7 000 and 16 000 unknowns for P1 "
        "and P2; a tangent with w times the entries of the element "
        "couplings, from the vertex volume term or contact pairs, counts its "
        "unknowns w^2 times), "
        "GMRES+Jacobi (inexact GMRES with diagonal preconditioning, "
        "dissertation 4.7.3), direct (sparse Cholesky or LU, see Direct "
        "solver) or "
        "GMRES+AMG (Trilinos ML algebraic multigrid; the entries below set "
        "its tolerance and hierarchy; automatic uses it with Forcing term = "
        "Eisenstat-Walker, Reuse preconditioner = true and AMG rotations = "
        "true, the settings measured: on the falling rods, 25 704 unknowns, "
        "21 s against the direct solver's 27 s and 47 s with AMG's own "
        "defaults; and it solves a step directly where GMRES does not "
        "converge within Maximum iterations with a fresh hierarchy either, "
        "as on an indefinite tangent, or where its restart cycles stagnate "
        "so that it cannot; the run summary counts these).",
        Patterns::Selection("automatic|GMRES+Jacobi|direct|GMRES+AMG"));
      prm.add_parameter(
        "Direct solver",
        direct_solver,
        "For Type = direct (and the direct steps of Type = automatic): "
        "Cholesky (CHOLMOD's sparse Cholesky factorization where the tangent "
        "is symmetric positive definite, its symbolic analysis kept while "
        "the sparsity pattern stays, and UMFPACK's LU where the tangent is "
        "not; the run summary counts those solves; with the energy line "
        "search a Newton step whose tangent is not positive definite is "
        "solved with its free diagonal shifted until it is, sec. 4.3.1), "
        "UMFPACK (deal.II's SparseDirectUMFPACK, sparse LU for every tangent, "
        "the Newton step of an indefinite tangent as it is) or MUMPS (the "
        "multifrontal LU through Trilinos Amesos, 1.1-1.9 times faster than "
        "UMFPACK on the meshes measured in doc/theory/04-solver.md sec. 4.5; "
        "a tangent it cannot factorize cuts the increment back). Measured "
        "(sec. 4.5.3): Cholesky took a third to a quarter of UMFPACK's "
        "linear-solve time on the scenes whose tangents stay definite (the "
        "sagging bars, the falling block, the coiling snake) and 2-3 times "
        "less per solve on clamped P1 cubes of 1 000 and 20 000-47 000 "
        "unknowns; where tangents turn indefinite its shifted steps took "
        "fewer Newton iterations on all but one scene measured (sec. 4.3.1: "
        "the wedge in the notch 142 -> 25, a twisted beam of 30 927 unknowns "
        "214 -> 39; the pinched tube 44 -> 50).",
        Patterns::Selection("UMFPACK|MUMPS|Cholesky"));
      prm.add_parameter(
        "AMG rotations",
        amg_rotations,
        "For Type = GMRES+AMG: false, the near-null space is the three "
        "translations; true, the six rigid-body modes (translations and "
        "rotations). Measured on a clamped 27 783-unknown P1 cube: half the "
        "GMRES iterations at 1e-8 (29 instead of 57), three times the "
        "hierarchy's setup (2.5 s instead of 0.7 s per solve).",
        Patterns::Bool());
      prm.add_parameter(
        "AMG aggregation",
        amg_aggregation,
        "For Type = GMRES+AMG: smoothed (the aggregates' tentative "
        "prolongators smoothed by damped Jacobi, ML's default smoothed "
        "aggregation), plain (the tentative prolongators as they are: a "
        "hierarchy built 2.4 times as fast, sparser coarse levels, more "
        "iterations) or automatic: plain where the hierarchy is kept "
        "(Reuse preconditioner, as Type = automatic sets it), smoothed "
        "where each solve builds its own. With plain, a kept hierarchy is "
        "refreshed for each matrix: its aggregates and transfers kept, its "
        "operators the Galerkin products of the new matrix "
        "(doc/theory/04-solver.md sec. 4.5.1). Measured with the hierarchy "
        "kept, two threads, plain against smoothed (sec. 4.5.2, "
        "2026-12-08): the apple snake 11.9-14.1 s against 14.7-15.0 s, the "
        "knee-scale tube 16.6-17.9 s against 17.8-17.9 s, the falling rods "
        "to t = 0.3 12.4-13.0 s against 12.6-13.0 s, the full knee's first "
        "8 increments 14.8-15.8 s against 27.9-29.5 s.",
        Patterns::Selection("plain|smoothed|automatic"));
      prm.add_parameter(
        "Forcing term",
        forcing_term,
        "For the iterative solvers: fixed (every solve to Relative "
        "tolerance) or Eisenstat-Walker (adaptive: loose while the Newton "
        "residual is large, tighter as it converges, never much beyond the "
        "Newton tolerance; Relative tolerance is then its upper bound; "
        "doc/theory/04-solver.md sec. 4.5.1).",
        Patterns::Selection("fixed|Eisenstat-Walker"));
      prm.add_parameter(
        "Definite steps",
        definite_steps,
        "For Type = GMRES+AMG (chosen or automatic), with Newton/Line "
        "search = energy: solve each Newton step by conjugate gradients "
        "with the AMG preconditioner, which stop at a direction of "
        "curvature that is not positive; the tangent's free diagonal is "
        "then shifted until they meet none (a Levenberg-Marquardt step, as "
        "the Cholesky factorization's steps are; doc/theory/04-solver.md "
        "sec. 4.3.2). False: GMRES for these steps too, shifted only where "
        "a step points uphill. Measured: the full knee (prm/"
        "knee_flexion.prm) 1 222 instead of 1 520 Newton iterations, 244 "
        "instead of 296 s; the coarse knee to 150 degrees 850 instead of "
        "1 076 Newton iterations on average over eight path variants; a "
        "twisted beam without contact (30 927 unknowns) 41 instead of 42 "
        "but 1 242 instead of 948 linear iterations, 13 instead of 10 s.",
        Patterns::Bool());
      prm.add_parameter(
        "Reuse preconditioner",
        reuse_preconditioner,
        "For Type = GMRES+AMG: keep the AMG hierarchy from one solve to "
        "the next (across Newton iterations, increments, time steps and "
        "new contact couplings) until the GMRES iterations it has cost "
        "beyond those it needed when it was built add up to a new one's "
        "setup (false: a new hierarchy for every solve); with AMG "
        "aggregation = plain its operators are refreshed for each matrix. "
        "Measured: with "
        "Forcing term = Eisenstat-Walker 30 % less linear-solve time on "
        "the quick knee-scale tube, and 21 hierarchies instead of 116 on "
        "the full one (prm/knee_tube.prm, "
        "doc/theory/04-solver.md sec. 4.5.1); with a fixed Relative "
        "tolerance of 0.1, twice the Newton iterations on a clamped block "
        "(a reused hierarchy reaches 0.1 where a fresh one, nearly exact, "
        "went far below), hence off by default.",
        Patterns::Bool());
      prm.add_parameter(
        "GMRES restart",
        gmres_restart,
        "For the iterative solvers: Krylov vectors GMRES keeps before it "
        "restarts (each holds one value per unknown), or 0: 150 with "
        "GMRES+AMG and 50 with GMRES+Jacobi. A restart discards what the "
        "basis has learnt, and an AMG iteration costs several products, so "
        "a long basis pays: on 212 tangents of the full knee (every 8th "
        "of a run, solved in its order), GMRES+AMG took 8 677 iterations and 29.9-31.2 "
        "s restarted after 50 and 7 079 and 21.3-21.4 s after 150; a Jacobi "
        "iteration costs one product, and its best restart is about 50 "
        "(doc/theory/04-solver.md sec. 4.5.2).",
        Patterns::Integer(0));
      prm.add_parameter("Relative tolerance",
                        relative_tolerance,
                        "Stop the iterative solvers when the linear "
                        "residual has fallen by this factor (0..1; 0.1 = the "
                        "inexact Newton method of the dissertation).",
                        Patterns::Double(0., 1.));
      prm.add_parameter("Maximum iterations",
                        max_iterations,
                        "Iteration cap of the iterative solvers (>= 1); "
                        "reaching it is not an error, the Newton loop "
                        "continues.",
                        Patterns::Integer(1));
      prm.leave_subsection();
    }


    LinearSolver::LinearSolver(
      const Parameters                  &parameters,
      const std::vector<Vector<double>> &near_null_space)
      : parameters(parameters)
      , null_space_dimension(
          std::min<std::size_t>(near_null_space.size(),
                                parameters.amg_rotations ? 6 : 3))
    {
      for (unsigned int k = 0; k < null_space_dimension; ++k)
        null_space.insert(null_space.end(),
                          near_null_space[k].begin(),
                          near_null_space[k].end());
      AssertThrow(parameters.type == "GMRES+Jacobi" ||
                    parameters.type == "direct" ||
                    parameters.type == "GMRES+AMG" ||
                    parameters.type == "automatic",
                  ExcMessage("Linear solver: unknown Type '" + parameters.type +
                             "'; use automatic, GMRES+Jacobi, direct or "
                             "GMRES+AMG"));
    }


    double
    LinearSolver::forcing(const double r,
                          const double r_previous,
                          const double eta_previous,
                          const double tolerance) const
    {
      const double eta_max = parameters.relative_tolerance;
      if (parameters.forcing_term == "fixed" || !(r_previous > 0.))
        return eta_max;
      const double gamma = 0.9, alpha = 2.;
      double       eta       = gamma * std::pow(r / r_previous, alpha);
      const double safeguard = gamma * std::pow(eta_previous, alpha);
      if (safeguard > 0.1)
        eta = std::max(eta, safeguard);
      if (r > 0.)
        eta = std::max(eta, 0.5 * tolerance / r);
      return std::min(eta, eta_max);
    }


    unsigned int
    LinearSolver::solve_amg(const SparseMatrix<double> &K,
                            Vector<double>             &x,
                            const Vector<double>       &b,
                            const double                target,
                            const bool                  stop_on_stagnation,
                            bool                       &converged,
                            bool                       *negative_curvature,
                            Vector<double>             *direction) const
    {
      // a hierarchy of a matrix of another size (another problem) is no
      // preconditioner of this one
      if (amg && amg->m() != K.m())
        amg.reset();
      // plain aggregation: a kept hierarchy is refreshed for this matrix
      // (doc/theory/04-solver.md sec. 4.5.1); not with smoothed
      // aggregation, whose prolongators hold a row's whole neighbourhood:
      // there the Galerkin products cost more than the iterations they save
      const bool smoothed  = parameters.aggregation() == "smoothed";
      bool       refreshed = false;
      if (!amg)
        {
          amg = std::make_unique<AMGPreconditioner>();
          amg->initialize(K, null_space, null_space_dimension, smoothed);
          fresh_rate = -1.;
        }
      else if (!smoothed && parameters.reuse_preconditioner)
        {
          try
            {
              amg->refresh(K, nonzeros);
            }
          catch (...)
            {
              amg.reset();
              throw;
            }
          refreshed = true;
        }
      // fresh: no solve has measured this hierarchy's rate yet (a solve
      // that starts at its target measures nothing)
      const bool fresh = fresh_rate < 0.;
      // the residual to start from: |b| for x = 0, else that of the iterate
      // a drifted hierarchy left (below)
      const double r0 = [&]() {
        if (x.l2_norm() == 0.)
          return b.l2_norm();
        Vector<double> r(b.size());
        return K.residual(r, x, b);
      }();
      // iterations per decade of residual: the hierarchy's quality, whatever
      // the tolerance
      const double decades =
        std::max(1., std::log10(std::max(r0 / target, 1.)));
      // a kept hierarchy is replaced once the iterations it has cost beyond
      // those it needed when fresh (fresh_rate per decade) add up to what a
      // new one costs to build, setup_cost iterations: rent until the rent
      // paid equals the price. Within a solve that is its budget; past it
      // GMRES goes on from the iterate with a new hierarchy
      // (doc/theory/04-solver.md sec. 4.5.1)
      const unsigned int budget =
        fresh ? parameters.max_iterations :
                std::min<unsigned int>(parameters.max_iterations,
                                       std::ceil(fresh_rate * decades +
                                                 setup_cost - excess));
      // a fresh hierarchy's solve that will fail anyway, where failing
      // means the direct solver from zero, stops once its restart cycles
      // stagnate (on the full knee's first 8 increments the one solve that
      // fell back ran to the cap of 1 000 iterations from 0.38 to 0.22
      // against a target of 0.16, 0.24 after 150)
      StagnationControl control(budget,
                                target,
                                fresh && stop_on_stagnation ?
                                  parameters.restart("GMRES+AMG") :
                                  0);
      converged = true;
      // CG's iterations with refreshed operators that refused (below)
      unsigned int refused_spent = 0;
      if (negative_curvature != nullptr)
        {
          // conjugate gradients, which stop at the first direction p of
          // curvature p.Kp that is not positive, or a preconditioned
          // residual with r.z not positive (a preconditioner that is not
          // positive definite either)
          // CG from x; whether it met r.z <= 0 (the preconditioner's
          // curvature) and not p.Kp <= 0
          const auto run_cg = [&]() {
            CurvatureWatch<NonzeroMatrix> A(*nonzeros);
            A.direction = direction;
            const CurvatureWatch<AMGPreconditioner> M(*amg);
            SolverCG<Vector<double>>                cg(control);
            cg.connect([&](const unsigned int, const double, const auto &) {
              return A.negative || M.negative ? SolverControl::failure :
                                                SolverControl::success;
            });
            converged = true;
            try
              {
                cg.solve(A, x, b, M);
              }
            catch (const SolverControl::NoConvergence &)
              {
                converged = false;
              }
            *negative_curvature = A.negative || M.negative;
            return M.negative && !A.negative;
          };
          const bool preconditioner_refused = run_cg();
          // a cycle refreshed with an indefinite tangent can be indefinite
          // itself, and its refusal tells nothing of the tangent: solved
          // again from zero with the operators of the last tangent solved
          // without a refusal, as a kept hierarchy was before refreshes
          if (preconditioner_refused && refreshed && amg->restore())
            {
              refused_spent = control.last_step();
              x             = 0.;
              run_cg();
            }
          if (*negative_curvature)
            {
              // a hierarchy built from this tangent is none for the
              // shifted one; a kept one (of a definite tangent) is
              if (fresh)
                amg.reset();
              return refused_spent + control.last_step();
            }
        }
      else
        {
          SolverGMRES<Vector<double>> gmres(control,
                                            gmres_settings(parameters,
                                                           "GMRES+AMG"));
          try
            {
              gmres.solve(*nonzeros, x, b, *amg);
            }
          catch (const SolverControl::NoConvergence &)
            {
              converged = false;
            }
        }
      if (control.last_step() == 0)
        {
          if (!parameters.reuse_preconditioner)
            amg.reset();
          return refused_spent;
        }
      // operators of a matrix solved without a refusal: kept beside the
      // next refreshed ones
      if (converged)
        amg->accept();
      const double rate = control.last_step() / decades;
      if (fresh)
        {
          fresh_rate = rate;
          excess     = 0.;
          // a hierarchy that did not bring its own tangent to the target (an
          // indefinite one) is not kept: with its rate as the yardstick, the
          // next solves would have run to the cap with it
          if (!converged)
            amg.reset();
        }
      else
        {
          excess += std::max(0.,
                             refused_spent + control.last_step() -
                               fresh_rate * decades);
          if (!converged || excess >= setup_cost)
            {
              // the matrix has drifted from the hierarchy's: a new one, now
              // (going on from the iterate reached) if this solve stopped
              // at its budget, else for the next solve
              const unsigned int spent = refused_spent + control.last_step();
              amg.reset();
              if (!converged)
                return spent + solve_amg(K,
                                         x,
                                         b,
                                         target,
                                         stop_on_stagnation,
                                         converged,
                                         negative_curvature,
                                         direction);
            }
        }
      if (!parameters.reuse_preconditioner)
        amg.reset();
      return refused_spent + control.last_step();
    }


    void
    LinearSolver::copy_nonzeros_of(const SparseMatrix<double> &K) const
    {
      const NonzeroMatrix *kept = amg ? amg->accepted_finest() : nullptr;
      nonzeros = nonzero_buffers[kept == nonzero_buffers[0].get() ? 1 : 0];
      nonzeros->copy_from(K);
    }


    unsigned int
    LinearSolver::solve(const SparseMatrix<double> &K,
                        Vector<double>             &x,
                        const Vector<double>       &b,
                        const double                relative_tolerance,
                        const bool                  from_x) const
    {
      const double tolerance  = relative_tolerance < 0. ?
                                  parameters.relative_tolerance :
                                  relative_tolerance;
      unsigned int iterations = 1;
      // Type = automatic: chosen by the size of this matrix
      const Parameters   chosen = parameters.resolved(K.m());
      const std::string &type   = chosen.type;
      if (!from_x)
        x = 0.;
      // GMRES, with either preconditioner, multiplies with the tangent's
      // nonzeros: bit for bit the products with K, at 40 % of their cost on
      // the full knee (doc/theory/04-solver.md sec. 4.5.2)
      if (type != "direct")
        copy_nonzeros_of(K);
      if (type == "direct")
        solve_direct(K, x, b);
      else if (type == "GMRES+AMG")
        {
          bool converged;
          iterations = solve_amg(K,
                                 x,
                                 b,
                                 tolerance * b.l2_norm(),
                                 chosen.direct_fallback,
                                 converged);
          // inexact Newton: the iterate after the cap is used as is, unless
          // the type was chosen automatically: then a system that a fresh
          // hierarchy did not solve either (an indefinite tangent) gets an
          // exact step. On the full-scale knee such solves ran to the cap
          // of 1 000 iterations twice (a fresh hierarchy the second time),
          // and again per tangent shift, at 5.8 ms per iteration
          if (!converged && chosen.direct_fallback)
            solve_direct_fallback(K, x, b);
        }
      else
        {
          // the target relative to |b|, not to the start's residual: the
          // same stop from x = 0, and no more than that from a given x
          SolverControl               control(parameters.max_iterations,
                                tolerance * b.l2_norm(),
                                false,
                                false);
          SolverGMRES<Vector<double>> gmres(control,
                                            gmres_settings(parameters,
                                                           "GMRES+Jacobi"));
          try
            {
              PreconditionJacobi<SparseMatrix<double>> jacobi;
              jacobi.initialize(K);
              gmres.solve(*nonzeros, x, b, jacobi);
            }
          catch (const SolverControl::NoConvergence &)
            {
              // inexact Newton: the iterate after the cap is used as is
            }
          iterations = control.last_step();
        }
      AssertThrow(std::isfinite(x.l2_norm()),
                  ExcMessage("the linear solver (" + type +
                             ") produced a non-finite Newton update; the "
                             "tangent matrix is singular or ill-conditioned"));
      return iterations;
    }


    LinearSolver::Definiteness
    LinearSolver::solve_definite(const SparseMatrix<double> &K,
                                 Vector<double>             &x,
                                 const Vector<double>       &b,
                                 const double                relative_tolerance,
                                 unsigned int               &iterations,
                                 Vector<double>             &direction,
                                 const bool test_symmetry) const
    {
      iterations = 0;
      direction.reinit(0);
      if (!factorizes_by_cholesky(K.m()))
        {
          Assert(tests_definiteness(K.m()), ExcInternalError());
          if (test_symmetry && !is_symmetric(K))
            return Definiteness::not_symmetric;
          copy_nonzeros_of(K);
          x = 0.;
          bool converged, negative = false;
          try
            {
              iterations = solve_amg(K,
                                     x,
                                     b,
                                     relative_tolerance * b.l2_norm(),
                                     false,
                                     converged,
                                     &negative,
                                     &direction);
            }
          catch (const SolveFailed &)
            {
              // a singular coarse operator: P^T K P of a positive definite
              // K is positive definite, so K is not (or the hierarchy
              // lost rank); refused like a negative curvature
              amg.reset();
              return Definiteness::not_positive_definite;
            }
          if (negative)
            return Definiteness::not_positive_definite;
          // no curvature that is not positive met, but not converged
          // either: the iterate descends (doc/theory/04-solver.md sec.
          // 4.3.2), but where Type = automatic chose GMRES+AMG the step is
          // made exact, as solve() makes it
          if (!converged && parameters.resolved(K.m()).direct_fallback)
            solve_direct_fallback(K, x, b);
          return Definiteness::positive_definite;
        }
      if (!cholesky)
        cholesky = std::make_unique<CholeskyFactorization>();
      if (!cholesky->factorize(K))
        return cholesky->was_symmetric() ? Definiteness::not_positive_definite :
                                           Definiteness::not_symmetric;
      cholesky->solve(x, b);
      iterations = 1;
      return Definiteness::positive_definite;
    }


    void
    LinearSolver::solve_direct_fallback(const SparseMatrix<double> &K,
                                        Vector<double>             &x,
                                        const Vector<double>       &b) const
    {
      // the nonzeros, as GMRES and AMG saw them: a pattern that kept
      // couplings no longer in contact
      // (NonlinearProblem::update_sparsity_pattern()) factorizes to the
      // same bits
      SparsityPattern      pattern;
      SparseMatrix<double> K_nonzeros;
      copy_nonzeros(K, pattern, K_nonzeros);
      solve_direct(K_nonzeros, x, b);
      ++n_direct_fallbacks;
    }


    void
    LinearSolver::solve_direct(const SparseMatrix<double> &K,
                               Vector<double>             &x,
                               const Vector<double>       &b) const
    {
      x = 0.;
      if (parameters.direct_solver == "MUMPS")
        {
          TrilinosWrappers::SparseMatrix A;
          A.reinit(K);
          SolverControl                                  control(1, 0.);
          TrilinosWrappers::SolverDirect::AdditionalData data(false,
                                                              "Amesos_Mumps");
          TrilinosWrappers::SolverDirect                 mumps(control, data);
          try
            {
              mumps.solve(A, x, b);
            }
          catch (const std::exception &)
            {
              // Amesos reports MUMPS' INFO(1) (-10: a zero pivot, -9: too
              // little workspace) only as an error number; the step is cut
              // back like a failed solve
              throw SolveFailed(
                "MUMPS could not factorize the tangent (a zero pivot or too "
                "little memory); try Direct solver = UMFPACK or Type = "
                "GMRES+AMG");
            }
        }
      else
        {
          // Cholesky where the tangent is symmetric positive definite. An
          // indefinite one costs a failed attempt before the LU, and
          // indefinite tangents come in runs (an increment through a
          // buckling or a contact snapping): after a failure the next
          // 1, 2, 4 or 8 solves go to the LU directly, the count doubled
          // by every failure in a row up to 8 and cleared by a success
          // (doc/theory/04-solver.md sec. 4.5.3)
          if (parameters.direct_solver == "Cholesky")
            {
              if (cholesky_skips > 0)
                --cholesky_skips;
              else
                {
                  if (!cholesky)
                    cholesky = std::make_unique<CholeskyFactorization>();
                  if (cholesky->factorize(K))
                    {
                      cholesky->solve(x, b);
                      cholesky_backoff = 0;
                      return;
                    }
                  cholesky_backoff =
                    std::min(8u, std::max(1u, 2 * cholesky_backoff));
                  cholesky_skips = cholesky_backoff;
                }
              ++n_cholesky_fallbacks;
            }
          SparseDirectUMFPACK lu;
          lu.initialize(K);
          lu.vmult(x, b);
        }
    }

  } // namespace Solvers
} // namespace TissueContact
