#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/dynamics/ida_integrator.h>

#include <deal.II/base/index_set.h>
#include <deal.II/numerics/matrix_tools.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <limits>

namespace TissueContact
{
  namespace Dynamics
  {
    namespace
    {
      /** Redirects the process's stderr into a temporary file while it
       * lives (restored by the destructor). */
      class StderrCapture
      {
      public:
        StderrCapture()
        {
          std::fflush(stderr);
          saved = ::dup(2);
          file  = std::tmpfile();
          if (file != nullptr && saved >= 0)
            ::dup2(::fileno(file), 2);
        }
        ~StderrCapture()
        {
          restore();
          if (file != nullptr)
            std::fclose(file);
        }
        /** Restore stderr; the first captured line containing @p text,
         * trimmed to one line ("" if none). */
        std::string
        first_line_with(const std::string &text)
        {
          restore();
          if (file == nullptr)
            return "";
          std::rewind(file);
          char buffer[4096];
          while (std::fgets(buffer, sizeof(buffer), file) != nullptr)
            {
              std::string line(buffer);
              while (!line.empty() &&
                     (line.back() == '\n' || line.back() == '\r'))
                line.pop_back();
              if (line.find(text) != std::string::npos)
                {
                  // IDA puts the message after the routine's name
                  std::string next;
                  if (std::fgets(buffer, sizeof(buffer), file) != nullptr)
                    next = buffer;
                  while (!next.empty() &&
                         (next.back() == '\n' || next.back() == '\r'))
                    next.pop_back();
                  const auto first = next.find_first_not_of(' ');
                  return line + (first == std::string::npos ?
                                   "" :
                                   " " + next.substr(first));
                }
            }
          return "";
        }

      private:
        void
        restore()
        {
          if (saved >= 0)
            {
              std::fflush(stderr);
              ::dup2(saved, 2);
              ::close(saved);
              saved = -1;
            }
        }
        int   saved = -1;
        FILE *file  = nullptr;
      };
    } // namespace

    IdaIntegrator::IdaIntegrator(
      const SUNDIALS::IDA<Vector<double>>::AdditionalData &data,
      const TimeIntegrator::Parameters                    &parameters,
      Solvers::NonlinearProblem                           &problem,
      const SparseMatrix<double>                          &mass)
      : data(data)
      , parameters(parameters)
      , problem(problem)
      , M(mass)
    {}


    unsigned int
    IdaIntegrator::integrate(State                                    &s,
                             const std::function<void(const State &)> &output)
    {
      const auto n = problem.n_dofs();
      // the load factor and the prescribed values and velocities at t
      const auto lambda = [&](const double t) {
        return parameters.ramp_time > 0. ?
                 std::min(1., t / parameters.ramp_time) :
                 1.;
      };
      const auto prescribed_velocity = [&](const double t) {
        std::map<types::global_dof_index, double> v;
        const double                              h = 1e-7;
        const auto                                minus =
          problem.prescribed_values(lambda(std::max(0., t - h)));
        const auto plus = problem.prescribed_values(lambda(t + h));
        for (const auto &p : plus)
          v[p.first] =
            (p.second - minus.at(p.first)) / (t + h - std::max(0., t - h));
        return v;
      };

      // the damping C = alpha M + beta K_0 + D, as the other schemes have it
      Vector<double> R(n), tmp(n);
      Damping        damping(parameters.rayleigh_alpha,
                      parameters.rayleigh_beta,
                      parameters.nodal_viscosity,
                      problem,
                      &M,
                      nullptr);
      damping.set_state(s.u, lambda(s.t));
      const auto damping_vmult = [&](Vector<double>       &Cx,
                                     const Vector<double> &x) {
        damping.vmult(Cx, x);
      };

      SUNDIALS::IDA<Vector<double>>             ida(data);
      SparseMatrix<double>                      J;
      SparseDirectUMFPACK                       J_inverse;
      double                                    alpha_ida = 0.;
      std::map<types::global_dof_index, double> fixed;
      n_jacobian_setups = 0;

      const auto split =
        [n](const Vector<double> &y, Vector<double> &a, Vector<double> &b) {
          a.reinit(n);
          b.reinit(n);
          for (types::global_dof_index i = 0; i < n; ++i)
            {
              a[i] = y[i];
              b[i] = y[n + i];
            }
        };

      ida.reinit_vector = [n](Vector<double> &v) { v.reinit(2 * n); };
      ida.residual      = [&](const double          t,
                         const Vector<double> &y,
                         const Vector<double> &y_dot,
                         Vector<double>       &F) {
        Vector<double> u, v, u_dot, v_dot;
        split(y, u, v);
        split(y_dot, u_dot, v_dot);
        problem.update_sparsity_pattern(u);
        if (!problem.assemble(u, lambda(t), R, nullptr))
          return 1; // an inverted element: IDA retries with a smaller step
        Vector<double> Fv(n);
        M.vmult(Fv, v_dot);
        Fv += R;
        damping_vmult(tmp, v);
        Fv += tmp;
        for (types::global_dof_index i = 0; i < n; ++i)
          {
            F[i]     = u_dot[i] - v[i];
            F[n + i] = Fv[i];
          }
        for (const auto &p : problem.prescribed_values(lambda(t)))
          F[p.first] = u[p.first] - p.second;
        for (const auto &p : prescribed_velocity(t))
          F[n + p.first] = v[p.first] - p.second;
        return 0;
      };
      ida.setup_jacobian = [&](const double          t,
                               const Vector<double> &y,
                               const Vector<double> &,
                               const double alpha) {
        Vector<double> u, v;
        split(y, u, v);
        problem.update_sparsity_pattern(u);
        J.reinit(problem.sparsity_pattern());
        if (!problem.assemble(u, lambda(t), R, &J))
          return 1;
        // K + alpha^2 M + alpha C
        for (auto it = M.begin(); it != M.end(); ++it)
          J.add(it->row(), it->column(), alpha * alpha * it->value());
        damping.add_to(J, alpha);
        // prescribed rows: identity (the right-hand side is set per solve)
        fixed.clear();
        for (const auto &p : problem.prescribed_values(lambda(t)))
          {
            fixed[p.first] = 0.;
            for (auto it = J.begin(p.first); it != J.end(p.first); ++it)
              it->value() = 0.;
            J.set(p.first, p.first, 1.);
          }
        alpha_ida = alpha;
        J_inverse.initialize(J);
        ++n_jacobian_setups;
        return 0;
      };
      ida.solve_with_jacobian =
        [&](const Vector<double> &rhs, Vector<double> &dst, const double) {
          Vector<double> r_u, r_v;
          split(rhs, r_u, r_v);
          // b = r_v + (alpha M + C) r_u on the free rows, r_u on the fixed
          Vector<double> b(r_v), du(n);
          M.vmult(tmp, r_u);
          b.add(alpha_ida, tmp);
          damping_vmult(tmp, r_u);
          b += tmp;
          for (const auto &p : fixed)
            b[p.first] = r_u[p.first];
          J_inverse.vmult(du, b);
          for (types::global_dof_index i = 0; i < n; ++i)
            {
              dst[i]     = du[i];
              dst[n + i] = alpha_ida * du[i] - r_u[i];
            }
          for (const auto &p : fixed)
            dst[n + p.first] = r_v[p.first];
          return 0;
        };
      ida.differential_components = [&]() {
        IndexSet differential(2 * n);
        differential.add_range(0, 2 * n);
        IndexSet algebraic(2 * n);
        for (const auto &p : problem.prescribed_values(lambda(s.t)))
          {
            algebraic.add_index(p.first);
            algebraic.add_index(n + p.first);
          }
        differential.subtract_set(algebraic);
        return differential;
      };
      double last_output  = s.t;
      double off_schedule = std::numeric_limits<double>::infinity();
      ida.output_step     = [&](const double          t,
                            const Vector<double> &y,
                            const Vector<double> &y_dot,
                            const unsigned int) {
        State o;
        split(y, o.u, o.v);
        Vector<double> u_dot;
        split(y_dot, u_dot, o.a);
        o.t         = t;
        last_output = t;
        // IDA returns before an output time only after a failure it
        // reports on the screen alone (too many steps, a failed step)
        const double k =
          std::round((t - data.initial_time) / data.output_period);
        if (std::abs(t - data.initial_time - k * data.output_period) >
              1e-8 * data.output_period &&
            std::abs(t - data.final_time) > 1e-8 * data.output_period)
          off_schedule = std::min(off_schedule, t);
        if (output)
          output(o);
      };

      // consistent initial values: y_dot = (v, a) with M a = -R - C v
      Vector<double> y(2 * n), y_dot(2 * n);
      {
        SparseMatrix<double> A(problem.sparsity_pattern());
        problem.assemble(s.u, lambda(s.t), R, nullptr);
        for (auto it = M.begin(); it != M.end(); ++it)
          A.add(it->row(), it->column(), it->value());
        Vector<double> rhs(R), a(n);
        damping_vmult(tmp, s.v);
        rhs += tmp;
        rhs *= -1.;
        std::map<types::global_dof_index, double> zero;
        for (const auto &p : problem.prescribed_values(lambda(s.t)))
          zero[p.first] = 0.;
        MatrixTools::apply_boundary_values(zero, A, a, rhs, true);
        SparseDirectUMFPACK A_inverse;
        A_inverse.initialize(A);
        A_inverse.vmult(a, rhs);
        for (types::global_dof_index i = 0; i < n; ++i)
          {
            y[i]         = s.u[i];
            y[n + i]     = s.v[i];
            y_dot[i]     = s.v[i];
            y_dot[n + i] = a[i];
          }
      }
      unsigned int steps = 0;
      // SUNDIALS prints its errors on stderr, several lines each: keep them
      // and report the first as one line of the failure instead
      StderrCapture ida_messages;
      try
        {
          steps = ida.solve_dae(y, y_dot);
        }
      catch (const ExceptionBase &e)
        {
          // SUNDIALS' own error codes (a failed step, a convergence test
          // failure) come as deal.II exceptions
          const std::string said = ida_messages.first_line_with("IDA");
          throw SolveFailed(error_message(e) +
                            (said.empty() ? "" : " (IDA: " + said + ")"));
        }
      const std::string said = ida_messages.first_line_with("IDA ERROR");
      // IDA reports some failures (too many steps before an output time)
      // only on the screen: check that it got to the end
      const double stopped = std::min(off_schedule, last_output);
      if (!std::isinf(off_schedule) ||
          last_output < data.final_time - 1e-9 * data.final_time)
        throw SolveFailed("IDA stopped at t = " + std::to_string(stopped) +
                          " before an output time (too many steps or a "
                          "failed step: loosen the tolerances or shorten the "
                          "output interval)" +
                          (said.empty() ? "" : "; IDA said: " + said));
      split(y, s.u, s.v);
      Vector<double> u_dot;
      split(y_dot, u_dot, s.a);
      s.t = data.final_time;
      return steps;
    }
  } // namespace Dynamics
} // namespace TissueContact
