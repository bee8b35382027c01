#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/base/parameter_tools.h>
#include <tissue_contact/base/timing.h>
#include <tissue_contact/solvers/newton_solver.h>

#include <deal.II/base/parallel.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace TissueContact
{
  namespace Solvers
  {
    namespace
    {
      /** The shifts sigma = 10^e of a definite step (doc/theory/
       * 04-solver.md sec. 4.3.1): from 10^min_shift (a change of the
       * step at the Newton tolerance's level) to 10^max_shift (the
       * diagonal a hundred times over: a step of a hundredth of a
       * Jacobi step's length). */
      constexpr int min_shift = -6;
      constexpr int max_shift = 2;
      /** A direction p of curvature p.Kp <= 0 that conjugate gradients met
       * asks for a shift of at least sigma - p.Kp / p.Dp; the ladder goes
       * on from the decade that holds this many times that, if it is above
       * the next rung (doc/theory/04-solver.md sec. 4.3.2: on eight
       * variants of the coarse knee to 150 degrees, margins of 2 and 10
       * took 850 and 976 Newton iterations on average, GMRES's steps
       * 1 076). */
      constexpr double shift_margin = 2.;

      /**
       * The step's constraint du = 0 on the prescribed DoFs, as
       * MatrixTools::apply_boundary_values() with zero values and
       * eliminated columns leaves the system (the same numbers): their rows
       * and columns of @p K zeroed but for the diagonal, @p rhs and @p du
       * zero there (rhs as 0 times the diagonal). One pass over the rows,
       * on the threads; deal.II's function searches each column entry in
       * its row, 3 % of the full knee's two-thread profile.
       */
      void
      constrain_prescribed(SparseMatrix<double>             &K,
                           const std::vector<unsigned char> &prescribed,
                           Vector<double>                   &rhs,
                           Vector<double>                   &du)
      {
        // a square SparseMatrix stores a row's values one after the other,
        // the diagonal first: a prescribed row's others are zeroed in one
        // sweep, a free row's where the column is prescribed (through its
        // iterators and with the flags as bits, this took 2.3 % of the
        // first 8 increments of the full knee)
        const SparsityPattern &pattern = K.get_sparsity_pattern();
        parallel::apply_to_subranges(
          types::global_dof_index(0),
          K.m(),
          [&](const types::global_dof_index begin,
              const types::global_dof_index end) {
            for (types::global_dof_index i = begin; i < end; ++i)
              {
                double            *v      = &K.diag_element(i);
                const unsigned int length = pattern.row_length(i);
                if (prescribed[i])
                  {
                    std::fill(v + 1, v + length, 0.);
                    rhs[i] = 0. * v[0];
                    du[i]  = 0.;
                  }
                else
                  for (unsigned int k = 1; k < length; ++k)
                    if (prescribed[pattern.column_number(i, k)])
                      v[k] = 0.;
              }
          },
          1000);
      }
    } // namespace

    void
    IncrementalNewtonSolver::Parameters::declare_parameters(
      ParameterHandler &prm)
    {
      prm.enter_subsection("Load stepping");
      prm.add_parameter("Initial increment",
                        initial_increment,
                        "First increment of the load factor (0 -> 1); "
                        "0..1.",
                        Patterns::Double(0., 1.));
      prm.add_parameter("Minimum increment",
                        minimum_increment,
                        "If a failed increment would be cut below this "
                        "size (0..1), the run stops with an error.",
                        Patterns::Double(0., 1.));
      prm.add_parameter("Maximum increment",
                        maximum_increment,
                        "Upper bound of the load increment (0..1).",
                        Patterns::Double(0., 1.));
      prm.add_parameter("Growth factor",
                        growth_factor,
                        "Factor (>= 1) by which the increment grows after an "
                        "easy increment.",
                        Patterns::Double(1.));
      prm.add_parameter("Easy iterations",
                        easy_iterations,
                        "An increment that converged within this many Newton "
                        "iterations (>= 1) is easy: the next one may grow.",
                        Patterns::Integer(1));
      add_selection<bool>(prm,
                          "Predictor",
                          two_point_predictor,
                          {{"two-point", true}, {"constant", false}},
                          "Initial guess of an increment: extrapolate the "
                          "last two converged states (two-point) or start "
                          "from the last one (constant).");
      prm.leave_subsection();

      prm.enter_subsection("Newton");
      prm.add_parameter("Maximum iterations",
                        max_iterations,
                        "Newton iterations per increment (>= 1) before it "
                        "is cut back.",
                        Patterns::Integer(1));
      prm.add_parameter("Residual tolerance",
                        residual_tolerance,
                        "Converged when |R| on the free DoFs is below this "
                        "fraction (0 ... 0.1) of the force scale (applied "
                        "loads or reactions, whichever is larger); a larger "
                        "one would accept the unloaded state. Where the "
                        "residual's rounding floor is above it (a body many "
                        "orders stiffer than the load), up to 1e3 times it, "
                        "the floor is used and the log says 'converged to "
                        "rounding' (doc/theory/04-solver.md sec. 4.2.1).",
                        Patterns::Double(0., 0.1));
      prm.add_parameter("Absolute tolerance",
                        absolute_tolerance,
                        "Converged when |R| on the free DoFs is below this "
                        "value (force units, >= 0; for unloaded problems).",
                        Patterns::Double(0.));
      prm.add_parameter("Maximum line search halvings",
                        max_halvings,
                        "LOOP 3: halve the Newton step at most this often "
                        "(>= 0) looking for a step with no inverted element "
                        "and a smaller residual.",
                        Patterns::Integer(0));
      add_selection<bool>(
        prm,
        "Nonlinear solver",
        use_kinsol,
        {{"Newton", false}, {"KINSOL", true}},
        "Solver of each load increment (and implicit time step): the "
        "project's Newton loop with line search and quasi-viscosity, or "
        "SUNDIALS' KINSOL (settings in the subsection KINSOL) with the same "
        "residual, tangent and linear solver.");
      kinsol.declare_parameters(prm);
      add_selection<bool>(
        prm,
        "Line search",
        energy_line_search,
        {{"residual", false}, {"energy", true}},
        "What a line-search step must decrease: the potential energy "
        "(Armijo; falls back to the residual where the energy change is at "
        "rounding level or the step is not a descent direction), or the "
        "residual norm (the dissertation's; it crawls in steps of 1/64 on "
        "bending, where the residual grows along a descent direction: "
        "doc/theory/04-solver.md sec. 4.3).");
      prm.add_parameter("Quasi-viscosity",
                        quasi_viscosity,
                        "Add the nodal quasi-viscosity D/dt to the tangent "
                        "(dissertation eq. 4.51): regularizes Newton near "
                        "bifurcations; the solution is unchanged.",
                        Patterns::Bool());
      prm.add_parameter("Viscosity factor",
                        viscosity_factor,
                        "eta in D_a = eta * sum_e mu_e h_e / n_e, a fraction "
                        "(>= 0, dimensionless) of the stiffness diagonal.",
                        Patterns::Double(0.));
      prm.add_parameter("Viscosity time step",
                        viscosity_time_step,
                        "dt of the quasi-viscosity (> 0; in load-factor "
                        "units, dissertation: 1).",
                        Patterns::Double(1e-300));
      prm.leave_subsection();

      linear_solver.declare_parameters(prm);
    }


    void
    IncrementalNewtonSolver::Parameters::parse_parameters(ParameterHandler &)
    {
      AssertThrow(minimum_increment > 0. &&
                    minimum_increment <= initial_increment &&
                    initial_increment <= maximum_increment,
                  ExcMessage("Load stepping: need 0 < Minimum increment <= "
                             "Initial increment <= Maximum increment"));
    }


    IncrementalNewtonSolver::IncrementalNewtonSolver(
      const Parameters &parameters)
      : parameters(parameters)
    {}


    void
    IncrementalNewtonSolver::newton(NonlinearProblem  &problem,
                                    Vector<double>    &u,
                                    const double       load_factor,
                                    const unsigned int increment,
                                    SolveStatistics   &statistics,
                                    TimerOutput       *timer)
    {
      const auto n = problem.n_dofs();
      if (K.empty() || K.m() != n)
        K.reinit(problem.sparsity_pattern());
      if (parameters.quasi_viscosity && viscosity.size() != n)
        viscosity =
          problem.quasi_viscosity_diagonal(parameters.viscosity_factor);

      const auto targets = problem.prescribed_values(load_factor);
      std::vector<unsigned char> prescribed(n, 0);
      for (const auto &t : targets)
        prescribed[t.first] = 1;

      const auto norms = [&](const Vector<double> &R) {
        double free = 0., reaction = 0.;
        for (types::global_dof_index i = 0; i < n; ++i)
          (prescribed[i] ? reaction : free) += R[i] * R[i];
        return std::make_pair(std::sqrt(free), std::sqrt(reaction));
      };

      // one linear solver (and so one AMG hierarchy while it stays good)
      // for all increments of a run
      if (!linear_solver)
        {
          const auto linear =
            parameters.linear_solver.resolved(n, problem.pattern_widening());
          linear_solver =
            std::make_unique<LinearSolver>(linear,
                                           linear.uses_near_null_space() ?
                                             problem.near_null_space() :
                                             std::vector<Vector<double>>());
        }
      Vector<double> R(n), R_trial(n), du(n), rhs(n), u_trial(n);
      const double   f_ext   = problem.external_force_norm(load_factor);
      double         r_first = 0., r_previous = 0., eta_previous = 0.;
      // full steps in a row that reduced |R| by less than 1 % with the
      // quasi-viscosity on: the viscosity, not the tangent, sets the step
      unsigned int viscous_stall = 0;
      // the rounding floor's perturbation of the free unknowns at rounding
      // level, delta_j = +-eps h (the same in every iteration), and its image
      const double   length_scale = problem.length_scale();
      Vector<double> delta(length_scale > 0. ? n : 0),
        K_delta(length_scale > 0. ? n : 0);
      for (types::global_dof_index i = 0; i < delta.size(); ++i)
        delta[i] = prescribed[i] ?
                     0. :
                     std::numeric_limits<double>::epsilon() * length_scale *
                       (((i * 2654435761u) >> 7) & 1u ? 1. : -1.);
      double last_step = 0.;
      // the exponent of the last definite step's shift in this
      // increment (below min_shift: none)
      int definite_shift = min_shift - 1;
      // whether the definite steps' symmetry test (conjugate gradients)
      // has passed in this increment: the tangent of one scene is
      // symmetric (an energy's Hessian) or not (a follower load) at every
      // iterate, and the test costs a product with K^T (serial)
      bool symmetry_tested = false, unsymmetric = false;
      // the energy at u when the line search computed it at the accepted
      // step (the start of the next line search), NaN otherwise
      double E_at_u = std::numeric_limits<double>::quiet_NaN();

      for (unsigned int it = 0;; ++it)
        {
          std::map<types::global_dof_index, double> gap;
          double                                    gap_norm = 0.;
          for (const auto &t : targets)
            {
              const double g = t.second - u[t.first];
              gap[t.first]   = g;
              gap_norm += g * g;
            }
          gap_norm = std::sqrt(gap_norm);

          bool valid;
          {
            const auto scope = time_section(timer, "assembly");
            // within an increment a new pattern keeps the couplings of
            // the one it replaces where the linear solves see only the
            // nonzeros (a pair that leaves and comes back calls for no
            // second build; doc/theory/05-contact.md sec. 7)
            if (problem.update_sparsity_pattern(
                  u, it > 0 && linear_solver->sees_nonzeros_only(n)))
              K.reinit(problem.sparsity_pattern());
            valid = problem.assemble(u, load_factor, R, &K);
          }
          if (!valid)
            throw SolveFailed("an element is inverted at the start of the "
                              "Newton iteration");
          const auto [r, reaction] = norms(R);
          if (!std::isfinite(r))
            throw SolveFailed(
              "the residual is not finite: an element is crushed to zero "
              "volume (J = 0) or its material law overflowed");
          const double load_tolerance =
            std::max(parameters.absolute_tolerance,
                     parameters.residual_tolerance * std::max(f_ext, reaction));
          // the residual's rounding floor (doc/theory/04-solver.md sec.
          // 4.2.1): |K delta| on the free DoFs for a change of the free
          // unknowns at rounding level, delta_j = +-eps h, which is how much
          // the rounding of F = I + grad u moves the internal forces. A
          // tolerance below it cannot be met; it replaces the tolerance up
          // to 1e3 times the load's (beyond that the solve fails and says
          // why: the result would not be accurate)
          double floor = 0.;
          if (length_scale > 0.)
            {
              K.vmult(K_delta, delta);
              for (types::global_dof_index i = 0; i < n; ++i)
                if (!prescribed[i])
                  floor += K_delta[i] * K_delta[i];
              floor = std::sqrt(floor);
            }
          const double tolerance =
            std::max(load_tolerance, std::min(floor, 1e3 * load_tolerance));

          // the residual the quasi-viscosity fades against: the first one
          // with the prescribed values in place (before that, as at the
          // start of a displacement-driven increment, |R| is that of the
          // last equilibrium, zero, and would keep the viscosity at full
          // strength through the whole increment)
          if (r_first == 0. && gap_norm == 0.)
            r_first = r;

          IterationInfo info;
          info.increment     = increment;
          info.load_factor   = load_factor;
          info.iteration     = it;
          info.residual_norm = r;

          if (gap_norm == 0. && r <= tolerance)
            {
              info.step_length = 0.;
              if (r > load_tolerance)
                {
                  info.at_rounding = true;
                  ++statistics.rounding_convergences;
                }
              if (on_iteration)
                on_iteration(info);
              return;
            }
          if (it > 0)
            viscous_stall = (parameters.quasi_viscosity && last_step == 1. &&
                             r > 0.99 * r_previous) ?
                              viscous_stall + 1 :
                              0;
          if (it == parameters.max_iterations)
            {
              std::ostringstream s;
              s << "Newton did not converge in " << it
                << " iterations (|R| = " << r << ", tolerance " << tolerance
                << ")";
              if (gap_norm > 0.)
                // with values still to prescribe a step is cut only where
                // it would invert an element (the line search below)
                s << ": the prescribed displacements are not reached (still "
                  << gap_norm
                  << " to go): every step toward them inverts an element";
              else if (floor > 1e3 * load_tolerance && r < 10. * floor)
                s << ": |R| is at the rounding floor of the internal forces ("
                  << floor
                  << "), more than 1e3 times the tolerance the load sets: "
                     "the stiffest body is too stiff for this load (its "
                     "forces are computed to eps times its modulus); "
                     "raise Newton/Absolute tolerance to "
                  << 10. * floor << " or soften the body";
              else if (viscous_stall >= 5)
                s << ": the quasi-viscosity limits every step (the last "
                  << viscous_stall
                  << " full steps reduced |R| by less than 1 %; its "
                     "diagonal scales with the shear modulus, so a stiff "
                     "body resting on a soft one barely moves); set "
                     "Newton/Quasi-viscosity = false or a smaller Viscosity "
                     "factor";
              throw SolveFailed(s.str());
            }

          // LOOP 2: (K + D/dt) du = -R, du = gap on prescribed DoFs
          {
            const auto scope = time_section(timer, "linear solve");
            // quasi-viscosity D/dt_k with dt_k = dt r_0 / r_k: full strength
            // at the start of the increment, fading as the residual falls
            // so that Newton keeps its quadratic rate near the solution
            if (parameters.quasi_viscosity)
              {
                const double c =
                  (r_first > 0. ? std::min(1., r / r_first) : 1.) /
                  parameters.viscosity_time_step;
                for (types::global_dof_index i = 0; i < n; ++i)
                  K.diag_element(i) += c * viscosity[i];
              }
            rhs = R;
            rhs *= -1.;
            du = 0.;
            // a prescribed row keeps its assembled diagonal in
            // constrain_prescribed(); a node that only a contact pair
            // touches (a rigid body's) can bring one of 1e-47, a pivot a
            // factorization rightly calls zero: such a row gets the mean
            // diagonal of the free rows instead (the others keep theirs)
            double diagonal = 0.;
            for (types::global_dof_index i = 0; i < n; ++i)
              if (!prescribed[i])
                diagonal += std::abs(K.diag_element(i));
            diagonal = n > gap.size() ? diagonal / (n - gap.size()) : 0.;
            if (!(diagonal > 0.))
              diagonal = 1.;
            // and, for the definite steps (the Cholesky factorization or
            // conjugate gradients), a positive one: the row is decoupled and
            // its right-hand side zero, so the sign changes no entry of the
            // step, but a contact pair on a rigid body's node can make the
            // assembled one negative, and every tangent would be refused (12
            // such rows on the full knee after one increment; doc/theory/
            // 04-solver.md sec. 4.3.1)
            const bool definite_steps = linear_solver->tests_definiteness(n);
            for (const auto &g : gap)
              {
                double &d = K.diag_element(g.first);
                if (std::abs(d) < 1e-12 * diagonal)
                  d = diagonal;
                else if (definite_steps)
                  d = std::abs(d);
              }
            // du = lift + v: the lift carries the prescribed values, v (zero
            // there) solves K v = -R - K lift on the free rows. An iterative
            // solver's relative tolerance then measures the free rows only:
            // with the values in the right-hand side (diagonal times gap),
            // they would dominate its norm and GMRES stop once it met them
            Vector<double> &lift = R_trial; // free here, the line search's
            lift                 = 0.;
            for (const auto &g : gap)
              lift[g.first] = g.second;
            if (gap_norm > 0.)
              {
                rhs *= -1.;
                K.vmult_add(rhs, lift);
                rhs *= -1.;
              }
            constrain_prescribed(K, prescribed, rhs, du);
            const double eta =
              linear_solver->forcing(r, r_previous, eta_previous, tolerance);
            const unsigned int fallbacks = linear_solver->direct_fallbacks();
            const unsigned int lu_solves = linear_solver->cholesky_fallbacks();
            // the diagonal before any shift, its free entries' magnitudes
            // |K_ii| (0 on the prescribed rows: a shift's scale), and the
            // shift in K now
            Vector<double> K0, d0;
            double         sigma     = 0.;
            const auto     keep_base = [&]() {
              if (K0.size() > 0)
                return;
              K0.reinit(n);
              d0.reinit(n);
              for (types::global_dof_index i = 0; i < n; ++i)
                {
                  K0[i] = K.diag_element(i);
                  d0[i] = prescribed[i] ? 0. : std::abs(K0[i]);
                }
            };
            // the shift set to next (exactly, and changed by the
            // difference where it is added)
            const auto shift_to = [&](const double next, const bool set) {
              if (next == sigma)
                return;
              keep_base();
              for (types::global_dof_index i = 0; i < n; ++i)
                if (set)
                  K.diag_element(i) = K0[i] + next * d0[i];
                else
                  K.diag_element(i) += (next - sigma) * d0[i];
              sigma = next;
            };
            // where the linear solver tells (the Cholesky factorization,
            // conjugate gradients with AMG) a step along which the energy
            // falls comes from a positive definite matrix: the tangent if
            // it is one, else the tangent with its free diagonal shifted by
            // sigma |K_ii|, sigma = 10^e from one decade below the last
            // shift of this increment (or from 10^min_shift) up, past the
            // shift a direction of negative curvature asks for
            // (doc/theory/04-solver.md sec. 4.3.1, 4.3.2)
            bool           definite           = false;
            unsigned int   refused_iterations = 0;
            Vector<double> direction;
            if (parameters.energy_line_search && gap_norm == 0. &&
                definite_steps && !unsymmetric)
              {
                // the tangent itself first (e below min_shift)
                int e = min_shift - 1;
                while (!definite && e <= max_shift)
                  {
                    // set, not added: a sum of shifts that should cancel
                    // a negative entry exactly left a pivot of 1e-16 (the
                    // double well of solvers/static_solver)
                    shift_to(e < min_shift ? 0. : std::pow(10., e), true);
                    unsigned int its;
                    const auto   result = linear_solver->solve_definite(
                      K, du, rhs, eta, its, direction, !symmetry_tested);
                    symmetry_tested = true;
                    if (result == LinearSolver::Definiteness::not_symmetric)
                      {
                        unsymmetric = true;
                        break;
                      }
                    definite =
                      result == LinearSolver::Definiteness::positive_definite;
                    if (definite)
                      {
                        info.linear_iterations = its;
                        definite_shift         = e;
                        statistics.tangent_shifts += (sigma > 0.);
                        break;
                      }
                    refused_iterations += its;
                    e = e < min_shift ?
                          std::max(min_shift, definite_shift - 1) :
                          e + 1;
                    // a direction p with p.(K0 + sigma D)p <= 0: a shift
                    // sigma' is needed with sigma' > sigma - p.Kp / p.Dp;
                    // the next is at least shift_margin times that
                    if (direction.size() == n)
                      {
                        keep_base();
                        Vector<double> Kp(n);
                        K.vmult(Kp, direction);
                        double pDp = 0.;
                        for (types::global_dof_index i = 0; i < n; ++i)
                          pDp += d0[i] * direction[i] * direction[i];
                        const double needed = sigma - (direction * Kp) / pDp;
                        if (pDp > 0. && needed > 0.)
                          e = std::max<int>(
                            e, std::ceil(std::log10(shift_margin * needed)));
                      }
                  }
                // not symmetric, or not positive definite even so: the
                // tangent's own step by LU or GMRES, and the shifts below
                if (!definite)
                  shift_to(0., true);
              }
            if (!definite)
              info.linear_iterations = linear_solver->solve(K, du, rhs, eta);
            info.linear_iterations += refused_iterations;
            du += lift;
            r_previous   = r;
            eta_previous = eta;
            // an indefinite tangent (the penalty energy of contact is not
            // convex) can give a du along which the energy rises: shift the
            // free diagonal by sigma |K_ii|, sigma = 1e-4, 1e-3, ..., 1,
            // until du descends (a Levenberg-Marquardt shift; doc/theory/
            // 04-solver.md sec. 4.3). Past that, the residual merit below.
            // (a definite step descends but for rounding: then too)
            if (parameters.energy_line_search && gap_norm == 0.)
              {
                const auto slope = [&]() {
                  double d = 0.;
                  for (types::global_dof_index i = 0; i < n; ++i)
                    if (!prescribed[i])
                      d += R[i] * du[i];
                  return d;
                };
                for (int e = -4; e <= 0 && slope() >= 0.; ++e)
                  {
                    if (std::pow(10., e) <= sigma)
                      continue;
                    shift_to(std::pow(10., e), false);
                    // from the last solve's du: the shifted system is
                    // near it (on the full knee a quarter of the GMRES
                    // iterations were these solves from zero; doc/theory/
                    // 04-solver.md sec. 4.5.1)
                    info.linear_iterations +=
                      linear_solver->solve(K, du, rhs, eta, true);
                    ++statistics.tangent_shifts;
                  }
              }
            statistics.direct_fallbacks +=
              linear_solver->direct_fallbacks() - fallbacks;
            statistics.cholesky_fallbacks +=
              linear_solver->cholesky_fallbacks() - lu_solves;
          }

          // LOOP 3: line search. Energy merit (Armijo) when asked for and
          // available, once the prescribed values are met; residual merit
          // otherwise, or where the energy change is at rounding level, or
          // if du is not a descent direction (an indefinite tangent)
          double E0 = std::numeric_limits<double>::quiet_NaN(), slope = 0.;
          if (parameters.energy_line_search && gap_norm == 0.)
            {
              if (std::isfinite(E_at_u))
                E0 = E_at_u;
              else
                {
                  const auto scope = time_section(timer, "assembly");
                  E0               = problem.energy(u, load_factor);
                }
              for (types::global_dof_index i = 0; i < n; ++i)
                if (!prescribed[i])
                  slope += R[i] * du[i];
            }
          const bool use_energy = std::isfinite(E0) && slope < 0.;
          double     s          = 1.;
          bool       accepted   = false;
          E_at_u                = std::numeric_limits<double>::quiet_NaN();
          for (unsigned int h = 0; h <= parameters.max_halvings; ++h, s *= 0.5)
            {
              u_trial = u;
              u_trial.add(s, du);
              if (use_energy)
                {
                  double E;
                  {
                    const auto scope = time_section(timer, "assembly");
                    E                = problem.energy(u_trial, load_factor);
                  }
                  if (!std::isfinite(E))
                    continue; // an inverted element
                  E_at_u = E;
                  if (std::abs(E - E0) > 1e-12 * std::abs(E0))
                    {
                      if (E <= E0 + 1e-4 * s * slope)
                        {
                          accepted = true;
                          break;
                        }
                      continue;
                    }
                }
              bool trial_valid;
              {
                const auto scope = time_section(timer, "assembly");
                trial_valid =
                  problem.assemble(u_trial, load_factor, R_trial, nullptr);
              }
              if (!trial_valid)
                continue;
              const double r_trial = norms(R_trial).first;
              if (gap_norm > 0. || r_trial < r || r_trial <= tolerance)
                {
                  accepted = true;
                  break;
                }
            }
          if (!accepted)
            {
              std::ostringstream msg;
              msg << "the line search found no step without inverted "
                     "elements and with a smaller "
                  << (use_energy ? "energy" : "residual") << " after "
                  << parameters.max_halvings << " halvings (Newton iteration "
                  << it << ", |R| = " << r << ", tolerance " << tolerance
                  << ")";
              throw SolveFailed(msg.str());
            }
          u.swap(u_trial);
          last_step        = s;
          info.update_norm = s * du.l2_norm();
          info.step_length = s;
          ++statistics.newton_iterations;
          statistics.linear_iterations += info.linear_iterations;
          if (on_iteration)
            on_iteration(info);
        }
    }


    void
    IncrementalNewtonSolver::solve_at(NonlinearProblem  &problem,
                                      Vector<double>    &u,
                                      const double       load_factor,
                                      const unsigned int increment,
                                      SolveStatistics   &statistics,
                                      TimerOutput       *timer)
    {
      if (!parameters.use_kinsol)
        {
          newton(problem, u, load_factor, increment, statistics, timer);
          return;
        }
      // KINSOL's stopping test is on the largest residual entry: the force
      // scale is the applied load, or the residual of the initial guess
      // with the prescribed values in place for displacement-driven steps
      const auto     n = problem.n_dofs();
      Vector<double> guess(u), R(n);
      const auto     targets = problem.prescribed_values(load_factor);
      for (const auto &t : targets)
        guess[t.first] = t.second;
      double scale = problem.external_force_norm(load_factor);
      if (problem.assemble(guess, load_factor, R, nullptr))
        {
          for (const auto &t : targets)
            R[t.first] = 0.;
          scale = std::max(scale, R.linfty_norm());
        }
      const double       tolerance  = std::max(parameters.absolute_tolerance,
                                        parameters.residual_tolerance * scale);
      unsigned int       iterations = 0;
      const KinsolSolver kinsol(parameters.kinsol, parameters.linear_solver);
      (void)increment;
      (void)timer;
      try
        {
          kinsol.solve(problem, u, load_factor, tolerance, iterations);
        }
      catch (const SolveFailed &)
        {
          statistics.newton_iterations += iterations;
          throw;
        }
      statistics.newton_iterations += iterations;
    }


    SolveStatistics
    IncrementalNewtonSolver::solve(NonlinearProblem &problem,
                                   Vector<double>   &u,
                                   TimerOutput      *timer)
    {
      if (restart)
        state = *restart;
      else
        {
          state                = LoadState();
          state.increment_size = parameters.initial_increment;
          state.u_prev         = u;
        }
      restart.reset();
      SolveStatistics &statistics     = state.statistics;
      double          &lambda         = state.lambda;
      double          &lambda_prev    = state.lambda_prev;
      double          &increment_size = state.increment_size;
      bool            &have_previous  = state.have_previous;
      Vector<double>  &u_prev         = state.u_prev;
      Vector<double>   u_trial(u);

      while (lambda < 1. - 1e-12)
        {
          const double       lambda_new = std::min(1., lambda + increment_size);
          const unsigned int its_before = statistics.newton_iterations;

          // two-point predictor on the free DoFs, prescribed DoFs at their
          // exact targets (a linear extrapolation of a rotation would
          // stretch the boundary)
          u_trial              = u;
          bool used_prediction = false;
          if (parameters.two_point_predictor && have_previous)
            {
              const double c = (lambda_new - lambda) / (lambda - lambda_prev);
              u_trial.add(c, u, -c, u_prev);
              for (const auto &t : problem.prescribed_values(lambda_new))
                u_trial[t.first] = t.second;
              used_prediction = true;
            }
          // one nonlinear solve, and again after every outer
          // (augmented-Lagrangian) update the problem makes; the reason of
          // its failure, empty if it converged. A failed attempt restores
          // the multipliers of the increment's start.
          const std::vector<double> multipliers_at_start =
            problem.multipliers();
          const auto attempt = [&]() -> std::string {
            const auto solve = [&]() {
              solve_at(problem,
                       u_trial,
                       lambda_new,
                       statistics.increments + 1,
                       statistics,
                       timer);
            };
            try
              {
                solve();
                for (unsigned int k = 0; problem.update_multipliers(u_trial, k);
                     ++k)
                  {
                    ++statistics.multiplier_updates;
                    solve();
                  }
              }
            catch (const SolveFailed &e)
              {
                problem.set_multipliers(multipliers_at_start);
                return e.what();
              }
            return "";
          };
          std::string failure = attempt();
          if (!failure.empty() && used_prediction)
            {
              // the extrapolated guess may invert elements or lie outside
              // Newton's basin: retry from the last converged state before
              // cutting the increment
              if (on_cutback)
                on_cutback(lambda_new,
                           failure + "; retrying without the predictor");
              u_trial = u;
              failure = attempt();
            }

          if (failure.empty())
            {
              u_prev.swap(u);
              u.swap(u_trial);
              lambda_prev   = lambda;
              lambda        = lambda_new;
              have_previous = true;
              ++statistics.increments;
              if (statistics.newton_iterations - its_before <=
                  parameters.easy_iterations)
                increment_size =
                  std::min(parameters.maximum_increment,
                           increment_size * parameters.growth_factor);
              if (on_increment)
                on_increment(statistics.increments, lambda, u);
            }
          else
            {
              ++statistics.cutbacks;
              if (on_cutback)
                on_cutback(lambda_new, failure + "; halving the increment");
              increment_size *= 0.5;
              std::ostringstream msg;
              msg << "the static solve failed at load factor " << lambda_new
                  << " (last converged: " << lambda << "): " << failure
                  << "; the load increment fell below the minimum "
                  << parameters.minimum_increment
                  << ". Check the loads and boundary conditions, or try a "
                     "smaller Minimum increment"
                  << (parameters.quasi_viscosity ?
                        " or a smaller Viscosity factor" :
                        " or Quasi-viscosity = true");
              if (increment_size < parameters.minimum_increment)
                throw SolveFailed(msg.str());
            }
        }
      return statistics;
    }
  } // namespace Solvers
} // namespace TissueContact
