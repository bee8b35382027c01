#pragma once

#include <tissue_contact/dynamics/damping.h>
#include <tissue_contact/solvers/newton_solver.h>
#include <tissue_contact/solvers/nonlinear_problem.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/sundials/ida.h>

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace TissueContact
{
  namespace Dynamics
  {
    using namespace dealii;

    /** The time integration schemes (doc/theory/06-dynamics.md). */
    enum class Scheme
    {
      implicit_euler,     ///< backward Euler in velocity form
      newmark,            ///< Newmark (default: average acceleration)
      central_difference, ///< explicit, lumped mass
      quasistatic,        ///< no inertia: C v + R(u) = 0 by backward Euler
      ida, ///< SUNDIALS' IDA (Dynamics::IdaIntegrator), not a TimeIntegrator
    };

    /** Every scheme with its prm name ("implicit Euler", "Newmark",
     * "central difference", "quasistatic", "IDA"). */
    const std::vector<std::pair<std::string, Scheme>> &
    scheme_names();

    /** The prm name of @p scheme. */
    std::string
    scheme_name(const Scheme scheme);

    /** Displacement, velocity and acceleration at time t. */
    struct State
    {
      Vector<double> u, v, a;
      double         t = 0.;
    };

    /**
     * Time integration of @f$M\ddot u + C\dot u + R(u) = 0@f$ for a
     * NonlinearProblem whose assemble() gives the static residual
     * @f$R(u) = f_{int}(u) - f_{ext}@f$ (at load factor 1) and its tangent,
     * with the mass M (consistent, or lumped: a diagonal) and Rayleigh
     * damping @f$C = \alpha M + \beta K_0@f$ (K_0: the tangent at the
     * initial state). The implicit schemes solve each step with the
     * project's Newton solver (line search, prescribed DoFs, contact) on
     * the effective residual; the explicit scheme needs the residual only.
     */
    class TimeIntegrator
    {
    public:
      /**
       * The prm subsection "Time integration": the analysis (static or
       * dynamic), the scheme and its settings, the step, the end time, the
       * damping, the mass and IDA's settings (subsection "IDA").
       */
      struct Parameters
      {
        /** Analysis = dynamic: integrate in time; static (false): the
         * incremental static solve, and nothing here is used. */
        bool   dynamic = false;
        Scheme scheme  = Scheme::newmark;
        /** The (largest) time step and the end time. */
        double time_step = 0.01, end_time = 1.;
        /** Time between outputs (0: every step). */
        double output_interval = 0.;
        /** The lumped (HRZ) mass instead of the consistent one. */
        bool   lumped_mass    = false;
        double beta           = 0.25; ///< Newmark beta
        double gamma          = 0.5;  ///< Newmark gamma
        double rayleigh_alpha = 0., rayleigh_beta = 0.;
        /** The K of beta K: false, K_0, the tangent at the initial state;
         * true, the tangent at the start of each implicit step, K(u_n),
         * which follows the bodies' rotation (the explicit scheme and IDA
         * keep K_0). */
        bool rayleigh_beta_current = false;
        /** A time tau: the dissertation's nodal viscosity D_a = tau
         * sum_e mu_e h_e / n_e (the static solver's quasi-viscosity
         * diagonal, doc/theory/04 sec. 4.4) as a physical damping:
         * C = alpha M + beta K_0 + D. */
        double nodal_viscosity = 0.;
        /** Loads and prescribed motions grow linearly from 0 to their full
         * value over this time (0: applied at once). */
        double ramp_time = 0.;
        /** Growth factor of the step after a step that took at most
         * easy_iterations Newton iterations; the step is halved after a
         * failed one, down to minimum_step. */
        double       growth_factor   = 1.5;
        unsigned int easy_iterations = 3;
        double       minimum_step    = 1e-8;
        /** The explicit scheme stops (with an error) when the energy grows
         * beyond this factor of its initial value plus the work done. */
        double blow_up_factor = 1e6;
        /** SUNDIALS' IDA settings (Scheme = IDA); its times are replaced
         * by those of ida_data(). */
        SUNDIALS::IDA<Vector<double>>::AdditionalData ida;

        /** IDA's settings with the times of this section: from 0 to
         * End time, output every Output interval (or Time step). */
        SUNDIALS::IDA<Vector<double>>::AdditionalData
        ida_data() const;

        /** Enter "Time integration" and bind its entries to this object
         * (IDA's through its AdditionalData::add_parameters()). */
        void
        declare_parameters(ParameterHandler &prm);
        /** Check what was read. */
        void
        parse_parameters(ParameterHandler &prm);
      };

      /** @p mass_consistent or @p mass_lumped (at least one; the explicit
       * scheme needs the lumped one). The implicit steps are solved by
       * Newton with the settings @p newton. Steps grow at most to
       * parameters.time_step when parameters.growth_factor > 1. */
      TimeIntegrator(
        const Parameters                                   &parameters,
        Solvers::NonlinearProblem                          &problem,
        const SparseMatrix<double>                         *mass_consistent,
        const Vector<double>                               *mass_lumped,
        const Solvers::IncrementalNewtonSolver::Parameters &newton = {});

      /** Set @p s.a from the equation of motion at @p s.u, @p s.v (the
       * acceleration the implicit schemes start from). */
      void
      initialize(State &s);

      /**
       * Advance @p s by one step of size @p dt (the implicit schemes cut
       * it back and retry from @p s while Newton fails). Returns the step
       * actually taken; @p next_dt gets the suggested next step. Throws
       * SolveFailed naming the time and the reason when the step falls
       * below the minimum, or when the explicit scheme blows up.
       */
      double
      step(State &s, const double dt, double &next_dt);

      /** @f$\frac12 v^T M v@f$ */
      double
      kinetic_energy(const State &s) const;

      /** Apply the mass to a vector: @p Mx = M x (lumped if that is all
       * there is). */
      void
      mass_vmult(Vector<double> &Mx, const Vector<double> &x) const;

      /** The damping C = alpha M + beta K + D (set up by initialize());
       * the power it dissipates at velocity v is v^T C v. */
      const Damping &
      damping() const
      {
        return damping_operator;
      }

      /** The load factor at time @p t (Parameters::ramp_time). */
      double
      load_factor(const double t) const;

      /** The kinetic-energy scale of the explicit scheme's blow-up check,
       * and whether its first step has set it: what a checkpoint keeps of
       * the integrator besides the State. */
      std::pair<double, bool>
      blow_up_reference() const
      {
        return {reference_energy, !first_explicit_step};
      }

      /** Restore blow_up_reference() (a restarted run). */
      void
      restore_blow_up_reference(const std::pair<double, bool> &reference)
      {
        reference_energy    = reference.first;
        first_explicit_step = !reference.second;
      }

      /** Newton iterations of the last implicit step. */
      unsigned int last_iterations = 0;
      /** Its linear solves made by LU instead of Cholesky (Linear
       * solver/Direct solver = Cholesky; SolveStatistics). */
      unsigned int last_lu_solves = 0;

      /** While set, assembly and linear solves are timed as the sections
       * "assembly" and "linear solve" of @p timer (null: not timed). */
      void
      set_timer(TimerOutput *timer)
      {
        this->timer = timer;
      }

      const Parameters parameters;

    private:
      Solvers::NonlinearProblem  &problem;
      const SparseMatrix<double> *M;
      const Vector<double>       *M_lumped;
      Damping                     damping_operator;
      /** One Newton solver for all steps: its matrix is allocated once
       * (it is rebuilt only when the problem's sparsity pattern changes). */
      Solvers::IncrementalNewtonSolver newton;
      TimerOutput                     *timer               = nullptr;
      double                           reference_energy    = 0.;
      bool                             first_explicit_step = true;

      double
      implicit_step(State &s, const double dt);
      void
      explicit_step(State &s, const double dt);
    };
  } // namespace Dynamics
} // namespace TissueContact
