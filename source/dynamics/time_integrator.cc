#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/base/parameter_tools.h>
#include <tissue_contact/dynamics/time_integrator.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/numerics/matrix_tools.h>

#include <limits>
#include <sstream>

// Symbols follow doc/theory/06-dynamics.md.

namespace TissueContact
{
  namespace Dynamics
  {
    namespace
    {
      /**
       * The residual of one implicit step as a NonlinearProblem in the
       * end-of-step displacement u: @f$G(u) = M a(u) + C v(u) + R(u)@f$
       * with the scheme's a(u), v(u), and the tangent
       * @f$K(u) + c_M M + c_C C@f$.
       */
      class EffectiveProblem : public Solvers::ForwardingProblem
      {
      public:
        EffectiveProblem(const TimeIntegrator       &integrator,
                         Solvers::NonlinearProblem  &problem,
                         const SparseMatrix<double> *M,
                         const Vector<double>       *M_lumped,
                         const State                &s,
                         const double                dt)
          : Solvers::ForwardingProblem(problem)
          , integrator(integrator)
          , M(M)
          , M_lumped(M_lumped)
          , s(s)
          , dt(dt)
        {
          const auto &p = integrator.parameters;
          if (p.scheme == Scheme::newmark)
            {
              c_M = 1. / (p.beta * dt * dt);
              c_C = p.gamma / (p.beta * dt);
            }
          else if (p.scheme == Scheme::quasistatic)
            {
              c_M = 0.;
              c_C = 1. / dt;
            }
          else
            {
              c_M = 1. / (dt * dt);
              c_C = 1. / dt;
            }
        }

        /** The scheme's velocity and acceleration at the end of the step
         * for the end displacement @p u. */
        void
        kinematics(const Vector<double> &u,
                   Vector<double>       &v,
                   Vector<double>       &a) const
        {
          const auto &p = integrator.parameters;
          v.reinit(u.size());
          a.reinit(u.size());
          if (p.scheme == Scheme::newmark)
            {
              // a = (u - u_n - dt v_n) / (beta dt^2) - (1/(2 beta) - 1) a_n
              a = u;
              a -= s.u;
              a.add(-dt, s.v);
              a *= 1. / (p.beta * dt * dt);
              a.add(-(0.5 / p.beta - 1.), s.a);
              // v = v_n + dt ((1 - gamma) a_n + gamma a)
              v = s.v;
              v.add(dt * (1. - p.gamma), s.a, dt * p.gamma, a);
            }
          else
            {
              // v = (u - u_n) / dt, a = (v - v_n) / dt (quasistatic: no
              // inertia, a = 0)
              v = u;
              v -= s.u;
              v /= dt;
              if (p.scheme != Scheme::quasistatic)
                {
                  a = v;
                  a -= s.v;
                  a /= dt;
                }
            }
        }

        bool
        assemble(const Vector<double> &u,
                 const double          load_factor,
                 Vector<double>       &R,
                 SparseMatrix<double> *K) override
        {
          if (!inner.assemble(u, load_factor, R, K))
            return false;
          Vector<double> v, a, tmp(u.size());
          kinematics(u, v, a);
          integrator.mass_vmult(tmp, a);
          R += tmp;
          integrator.damping().vmult(tmp, v);
          R += tmp;
          if (K != nullptr)
            {
              if (M != nullptr)
                add_scaled(*K, c_M, *M);
              else
                for (types::global_dof_index i = 0; i < u.size(); ++i)
                  K->add(i, i, c_M * (*M_lumped)[i]);
              integrator.damping().add_to(*K, c_C);
            }
          return true;
        }
        /**
         * The incremental potential: Pi(u) + w(u_n) . d + d^T J_w d / 2,
         * d = u - u_n, with w(u) = M a(u) + C v(u) affine in u with the
         * symmetric Jacobian J_w = c_M M + c_C C; its gradient is G(u), so
         * the energy line search applies to time steps too.
         */
        double
        energy(const Vector<double> &u, const double load_factor) const override
        {
          const double Pi = inner.energy(u, load_factor);
          if (!std::isfinite(Pi))
            return Pi;
          Vector<double> v, a, w(u.size()), tmp(u.size()), d(u);
          d -= s.u;
          // w(u_n) = M a(u_n) + C v(u_n)
          kinematics(s.u, v, a);
          integrator.mass_vmult(w, a);
          integrator.damping().vmult(tmp, v);
          w += tmp;
          // J_w d = c_M M d + c_C C d
          Vector<double> Jd(u.size());
          integrator.mass_vmult(Jd, d);
          Jd *= c_M;
          integrator.damping().vmult(tmp, d);
          Jd.add(c_C, tmp);
          return Pi + w * d + 0.5 * (d * Jd);
        }


      private:
        const TimeIntegrator       &integrator;
        const SparseMatrix<double> *M;
        const Vector<double>       *M_lumped;
        const State                &s;
        const double                dt;
        double                      c_M = 0., c_C = 0.;
      };
    } // namespace


    const std::vector<std::pair<std::string, Scheme>> &
    scheme_names()
    {
      static const std::vector<std::pair<std::string, Scheme>> names = {
        {"Newmark", Scheme::newmark},
        {"implicit Euler", Scheme::implicit_euler},
        {"central difference", Scheme::central_difference},
        {"IDA", Scheme::ida},
        {"quasistatic", Scheme::quasistatic}};
      return names;
    }


    std::string
    scheme_name(const Scheme scheme)
    {
      for (const auto &n : scheme_names())
        if (n.second == scheme)
          return n.first;
      Assert(false, ExcInternalError());
      return "";
    }


    SUNDIALS::IDA<Vector<double>>::AdditionalData
    TimeIntegrator::Parameters::ida_data() const
    {
      auto data          = ida;
      data.initial_time  = 0.;
      data.final_time    = end_time;
      data.output_period = output_interval > 0. ? output_interval : time_step;
      data.ic_type       = SUNDIALS::IDA<Vector<double>>::AdditionalData::none;
      data.reset_type    = SUNDIALS::IDA<Vector<double>>::AdditionalData::none;
      return data;
    }


    namespace
    {
      /** Subsection "IDA": the entries of SUNDIALS' IDA the project uses,
       * bound to @p data and documented (deal.II's add_parameters() leaves
       * most undocumented, and declares times and initial-condition
       * corrections that the project sets itself: ida_data()). */
      void
      declare_ida_parameters(
        ParameterHandler                              &prm,
        SUNDIALS::IDA<Vector<double>>::AdditionalData &data)
      {
        prm.enter_subsection("IDA");
        prm.enter_subsection("Running parameters");
        prm.add_parameter("Initial step size",
                          data.initial_step_size,
                          "IDA's first time step (time units, > 0); it then "
                          "adapts the step to its error control.",
                          Patterns::Double(0.));
        prm.add_parameter("Minimum step size",
                          data.minimum_step_size,
                          "IDA stops with an error below this step (time "
                          "units, >= 0).",
                          Patterns::Double(0.));
        prm.add_parameter("Maximum order of BDF",
                          data.maximum_order,
                          "Highest order of IDA's backward differentiation "
                          "formulas (1..5); lower orders are more stable, "
                          "higher ones more accurate on smooth motion.",
                          Patterns::Integer(1, 5));
        prm.add_parameter("Maximum number of nonlinear iterations",
                          data.maximum_non_linear_iterations,
                          "Newton iterations per IDA step before it cuts the "
                          "step (>= 1).",
                          Patterns::Integer(1));
        prm.leave_subsection();
        prm.enter_subsection("Error control");
        prm.add_parameter("Absolute error tolerance",
                          data.absolute_tolerance,
                          "atol of IDA's local error test |e_i| <= rtol |y_i| "
                          "+ atol, in the units of y = (u, v) (length and "
                          "velocity); set it near the scale of the solution "
                          "(doc/theory/06-dynamics.md sec. 8).",
                          Patterns::Double(0.));
        prm.add_parameter("Relative error tolerance",
                          data.relative_tolerance,
                          "rtol of IDA's local error test (dimensionless, "
                          ">= 0).",
                          Patterns::Double(0.));
        prm.add_parameter("Ignore algebraic terms for error computations",
                          data.ignore_algebraic_terms_for_errors,
                          "Leave the algebraic equations (the prescribed "
                          "DoFs) out of the local error test.",
                          Patterns::Bool());
        prm.leave_subsection();
        prm.leave_subsection();
      }
    } // namespace


    void
    TimeIntegrator::Parameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Time integration");
      add_selection<bool>(
        prm,
        "Analysis",
        dynamic,
        {{"static", false}, {"dynamic", true}},
        "static: incremental loading to equilibrium (no mass); dynamic: "
        "integrate the equations of motion in time "
        "(doc/theory/06-dynamics.md).");
      add_selection<Scheme>(
        prm,
        "Scheme",
        scheme,
        scheme_names(),
        "Newmark (beta, gamma below; average acceleration by default: no "
        "numerical damping), implicit Euler (dissipative), central "
        "difference (explicit, lumped mass, stable below 2/omega_max), IDA "
        "(SUNDIALS' variable-order BDF with error control; settings in the "
        "subsection IDA, whose times are replaced by End time and Output "
        "interval), quasistatic (no inertia: the damping C = alpha M + beta "
        "K_0 as a viscosity, C v + f_int(u) = f_ext(t) by backward Euler; "
        "without damping a sequence of static solves).");
      declare_ida_parameters(prm, ida);
      prm.add_parameter("Time step",
                        time_step,
                        "The time step h (time units; > 0 for a dynamic "
                        "analysis): every step of the fixed-step schemes, "
                        "the largest one when Growth factor > 1, IDA's "
                        "output period when Output interval = 0.",
                        Patterns::Double(0.));
      prm.add_parameter("End time",
                        end_time,
                        "The simulated time at which the run stops (time "
                        "units; > 0 for a dynamic analysis); it starts at "
                        "t = 0 from rest.",
                        Patterns::Double(0.));
      prm.add_parameter("Minimum time step",
                        minimum_step,
                        "An implicit step whose Newton solve fails is halved "
                        "and retried; below this size (time units, >= 0) the "
                        "run stops.",
                        Patterns::Double(0.));
      prm.add_parameter("Growth factor",
                        growth_factor,
                        "After a step with at most 3 Newton iterations the "
                        "next may grow by this factor (>= 1; up to Time "
                        "step): a step cut back at an impact grows back "
                        "afterwards.",
                        Patterns::Double(1.));
      prm.add_parameter("Newmark beta",
                        beta,
                        "Newmark's beta in u_{n+1} = u_n + h v_n + h^2 "
                        "((1/2 - beta) a_n + beta a_{n+1}); 0 < beta <= 0.5 "
                        "(0.25 with gamma = 0.5: average acceleration, "
                        "unconditionally stable, no numerical damping).",
                        Patterns::Double(0., 0.5));
      prm.add_parameter("Newmark gamma",
                        gamma,
                        "Newmark's gamma in v_{n+1} = v_n + h ((1 - gamma) "
                        "a_n + gamma a_{n+1}); 0..1 (0.5: second order, no "
                        "numerical damping; > 0.5 damps high frequencies).",
                        Patterns::Double(0., 1.));
      prm.add_parameter("Rayleigh alpha",
                        rayleigh_alpha,
                        "alpha of the damping C = alpha M + beta K (1/time; "
                        ">= 0): mass-proportional, damps slow motion.",
                        Patterns::Double(0.));
      prm.add_parameter("Rayleigh beta",
                        rayleigh_beta,
                        "beta of C = alpha M + beta K (time; >= 0; K: see "
                        "Rayleigh tangent): stiffness-proportional, damps "
                        "fast vibration.",
                        Patterns::Double(0.));
      add_selection<bool>(
        prm,
        "Rayleigh tangent",
        rayleigh_beta_current,
        {{"initial", false}, {"step start", true}},
        "The K of beta K. initial: K_0, the tangent at the initial state "
        "(constant, but not objective: it over-damps slender bodies that "
        "have rotated, doc/theory/06-dynamics.md sec. 1); step start: the "
        "tangent at the start of every implicit step, which follows the "
        "rotation (one more assembly per step; the explicit scheme and IDA "
        "keep K_0).");
      prm.add_parameter(
        "Nodal viscosity",
        nodal_viscosity,
        "A time tau (>= 0): the dissertation's nodal viscosity D_a = tau "
        "sum_e mu_e h_e / n_e (the diagonal of the static solver's "
        "quasi-viscosity, doc/theory/04 sec. 4.4) added to the damping C as "
        "a physical damping; a node's viscous force D_a v equals the "
        "elastic force of its elements at the displacement tau v.",
        Patterns::Double(0.));
      add_selection<bool>(prm,
                          "Mass",
                          lumped_mass,
                          {{"consistent", false}, {"lumped", true}},
                          "The implicit schemes may use either; central "
                          "difference always uses the lumped (HRZ) mass.");
      prm.add_parameter("Ramp time",
                        ramp_time,
                        "Loads and prescribed motions grow linearly from "
                        "zero over this time (time units, >= 0; 0: applied "
                        "at t = 0).",
                        Patterns::Double(0.));
      prm.add_parameter("Output interval",
                        output_interval,
                        "Time between VTU outputs (time units, >= 0; 0: "
                        "every step).",
                        Patterns::Double(0.));
      prm.leave_subsection();
    }


    void
    TimeIntegrator::Parameters::parse_parameters(ParameterHandler &)
    {
      AssertThrow(!dynamic || (time_step > 0. && end_time > 0.),
                  ExcMessage("Time integration: a dynamic analysis needs "
                             "Time step > 0 and End time > 0"));
      AssertThrow(scheme != Scheme::newmark || beta > 0.,
                  ExcMessage("Time integration: Newmark beta must be > 0 "
                             "for the implicit Newmark scheme"));
    }


    TimeIntegrator::TimeIntegrator(
      const Parameters                                   &parameters,
      Solvers::NonlinearProblem                          &problem,
      const SparseMatrix<double>                         *mass_consistent,
      const Vector<double>                               *mass_lumped,
      const Solvers::IncrementalNewtonSolver::Parameters &newton_parameters)
      : parameters(parameters)
      , problem(problem)
      , M(mass_consistent)
      , M_lumped(mass_lumped)
      , damping_operator(parameters.rayleigh_alpha,
                         parameters.rayleigh_beta,
                         parameters.nodal_viscosity,
                         problem,
                         parameters.scheme == Scheme::central_difference ?
                           nullptr :
                           mass_consistent,
                         mass_lumped)
      , newton(newton_parameters)
    {
      AssertThrow(parameters.scheme != Scheme::ida,
                  ExcMessage("Scheme = IDA runs Dynamics::IdaIntegrator, not "
                             "a TimeIntegrator"));
      AssertThrow(M != nullptr || M_lumped != nullptr,
                  ExcMessage("time integration needs a mass matrix"));
      AssertThrow(parameters.scheme != Scheme::central_difference ||
                    M_lumped != nullptr,
                  ExcMessage("the central difference scheme needs the "
                             "lumped mass"));
      if (parameters.scheme == Scheme::central_difference)
        M = nullptr; // explicit: the lumped mass only
    }


    double
    TimeIntegrator::load_factor(const double t) const
    {
      return parameters.ramp_time > 0. ?
               std::min(1., t / parameters.ramp_time) :
               1.;
    }


    void
    TimeIntegrator::mass_vmult(Vector<double>       &Mx,
                               const Vector<double> &x) const
    {
      if (M != nullptr)
        M->vmult(Mx, x);
      else
        for (types::global_dof_index i = 0; i < x.size(); ++i)
          Mx[i] = (*M_lumped)[i] * x[i];
    }


    double
    TimeIntegrator::kinetic_energy(const State &s) const
    {
      if (parameters.scheme == Scheme::quasistatic)
        return 0.; // no inertia
      Vector<double> Mv(s.v.size());
      mass_vmult(Mv, s.v);
      return 0.5 * (s.v * Mv);
    }


    void
    TimeIntegrator::initialize(State &s)
    {
      const auto     n = problem.n_dofs();
      Vector<double> R(n);
      AssertThrow(problem.assemble(s.u, load_factor(s.t), R, nullptr),
                  ExcMessage("time integration: an element is inverted in "
                             "the initial state"));
      damping_operator.set_state(s.u, load_factor(s.t));
      // M a_0 = -R(u_0) - C v_0 on the free DoFs; prescribed: a_0 = 0
      Vector<double> rhs(n), Cv;
      damping_operator.vmult(Cv, s.v);
      rhs = R;
      rhs += Cv;
      rhs *= -1.;
      s.a.reinit(n);
      const auto prescribed = problem.prescribed_values(load_factor(s.t));
      if (parameters.scheme == Scheme::quasistatic)
        ; // no inertia: a = 0
      else if (M != nullptr)
        {
          SparseMatrix<double> A(problem.sparsity_pattern());
          add_scaled(A, 1., *M);
          std::map<types::global_dof_index, double> zero;
          for (const auto &t : prescribed)
            zero[t.first] = 0.;
          MatrixTools::apply_boundary_values(zero, A, s.a, rhs, true);
          Solvers::LinearSolver::Parameters direct;
          Solvers::LinearSolver(direct).solve(A, s.a, rhs);
        }
      else
        for (types::global_dof_index i = 0; i < n; ++i)
          if ((*M_lumped)[i] > 0. && prescribed.count(i) == 0)
            s.a[i] = rhs[i] / (*M_lumped)[i];
      reference_energy = kinetic_energy(s) + 0.5 * std::abs(s.u * R) +
                         std::numeric_limits<double>::min();
    }


    double
    TimeIntegrator::implicit_step(State &s, const double dt)
    {
      EffectiveProblem effective(*this, problem, M, M_lumped, s, dt);
      // predictor: constant velocity (the constant-acceleration one
      // carries the high-frequency content of a_n that Newmark does not
      // damp: initial residuals 50 times larger on prm/sagging_bars.prm)
      Vector<double> u = s.u;
      u.add(dt, s.v);
      const double lambda = load_factor(s.t + dt);
      for (const auto &t : problem.prescribed_values(lambda))
        u[t.first] = t.second;
      SolveStatistics statistics;
      try
        {
          newton.solve_at(effective, u, lambda, 0, statistics, timer);
        }
      catch (const SolveFailed &e)
        {
          last_iterations = statistics.newton_iterations;
          last_lu_solves  = statistics.cholesky_fallbacks;
          std::ostringstream msg;
          msg << "at t = " << s.t << " with step " << dt << ": " << e.what();
          throw SolveFailed(msg.str());
        }
      last_iterations = statistics.newton_iterations;
      last_lu_solves  = statistics.cholesky_fallbacks;
      Vector<double> v, a;
      effective.kinematics(u, v, a);
      s.u.swap(u);
      s.v.swap(v);
      s.a.swap(a);
      s.t += dt;
      return dt;
    }


    void
    TimeIntegrator::explicit_step(State &s, const double dt)
    {
      const auto n = s.u.size();
      // v_{n+1/2} = v_n + dt/2 a_n, u_{n+1} = u_n + dt v_{n+1/2}
      Vector<double> v_half = s.v;
      v_half.add(0.5 * dt, s.a);
      s.u.add(dt, v_half);
      const double lambda     = load_factor(s.t + dt);
      const auto   prescribed = problem.prescribed_values(lambda);
      for (const auto &t : prescribed)
        s.u[t.first] = t.second;
      Vector<double> R(n), Cv;
      bool           valid;
      {
        std::unique_ptr<TimerOutput::Scope> scope;
        if (timer != nullptr)
          scope = std::make_unique<TimerOutput::Scope>(*timer, "assembly");
        valid = problem.assemble(s.u, lambda, R, nullptr);
      }
      damping_operator.vmult(Cv, v_half);
      s.a = 0.;
      for (types::global_dof_index i = 0; i < n; ++i)
        if ((*M_lumped)[i] > 0. && prescribed.count(i) == 0)
          s.a[i] = -(R[i] + Cv[i]) / (*M_lumped)[i];
      s.v = v_half;
      s.v.add(0.5 * dt, s.a);
      s.t += dt;
      const double kinetic = kinetic_energy(s);
      // a body starting from rest at its reference state has no initial
      // energy to compare with: the first step's kinetic energy sets the
      // scale then (an instability grows geometrically from any scale)
      if (first_explicit_step)
        {
          reference_energy    = std::max(reference_energy, kinetic);
          first_explicit_step = false;
        }
      if (!valid || !std::isfinite(kinetic) ||
          kinetic > parameters.blow_up_factor * reference_energy)
        {
          std::ostringstream msg;
          msg << "the explicit central difference scheme is unstable at t = "
              << s.t << " with step " << dt
              << (valid ? " (the kinetic energy grew by more than a factor " :
                          " (an element inverted; the kinetic energy is ")
              << (valid ? parameters.blow_up_factor : kinetic)
              << "): choose a step below the stable estimate";
          throw SolveFailed(msg.str());
        }
    }


    double
    TimeIntegrator::step(State &s, const double dt, double &next_dt)
    {
      if (parameters.scheme == Scheme::central_difference)
        {
          explicit_step(s, dt);
          next_dt = dt;
          return dt;
        }
      if (parameters.rayleigh_beta != 0. && parameters.rayleigh_beta_current)
        damping_operator.set_state(s.u, load_factor(s.t));
      double      h = dt;
      std::string reason;
      while (h >= parameters.minimum_step)
        {
          State trial = s;
          try
            {
              implicit_step(trial, h);
            }
          catch (const SolveFailed &e)
            {
              reason = e.what();
              h *= 0.5; // cut back and retry from s
              continue;
            }
          s = std::move(trial);
          next_dt =
            last_iterations <= parameters.easy_iterations ?
              std::min(parameters.time_step, h * parameters.growth_factor) :
              h;
          return h;
        }
      std::ostringstream msg;
      msg << "time integration failed at t = " << s.t << ": the step was "
          << "halved from " << dt << " to " << h
          << ", below the Minimum time step " << parameters.minimum_step
          << ", and the implicit step still failed: " << reason
          << ". Try a smaller Time step, more Rayleigh damping, a smaller "
             "Penalty factor or the quasi-viscosity";
      throw SolveFailed(msg.str());
    }
  } // namespace Dynamics
} // namespace TissueContact
