#include <deal.II/lac/sparse_matrix.h>
#include <sstream>
#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/solvers/kinsol_solver.h>

namespace TissueContact
{
  namespace Solvers
  {
    namespace
    {
      /** The object add_parameters() binds the declared entries to; the
       * values are read back by name in parse(). */
      SUNDIALS::KINSOL<Vector<double>>::AdditionalData &
      declaration_target()
      {
        static SUNDIALS::KINSOL<Vector<double>>::AdditionalData data;
        return data;
      }
    } // namespace


    void
    KinsolSolver::Parameters::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("KINSOL");
      declaration_target().add_parameters(prm);
      prm.leave_subsection();
    }


    void
    KinsolSolver::Parameters::parse(ParameterHandler &prm)
    {
      using Data = SUNDIALS::KINSOL<Vector<double>>::AdditionalData;
      prm.enter_subsection("KINSOL");
      const std::string strategy = prm.get("Solution strategy");
      data.strategy              = strategy == "newton"     ? Data::newton :
                                   strategy == "linesearch" ? Data::linesearch :
                                   strategy == "fixed_point" ? Data::fixed_point :
                                                               Data::picard;
      data.maximum_non_linear_iterations =
        prm.get_integer("Maximum number of nonlinear iterations");
      data.function_tolerance =
        prm.get_double("Function norm stopping tolerance");
      data.step_tolerance = prm.get_double("Scaled step stopping tolerance");
      prm.enter_subsection("Fixed point and Picard parameters");
      data.anderson_subspace_size =
        prm.get_integer("Anderson acceleration subspace size");
      prm.leave_subsection();
      prm.enter_subsection("Linesearch parameters");
      data.maximum_beta_failures =
        prm.get_integer("Maximum number of beta-condition failures");
      prm.leave_subsection();
      prm.enter_subsection("Newton parameters");
      data.no_init_setup = prm.get_bool("No initial matrix setup");
      data.maximum_setup_calls =
        prm.get_integer("Maximum iterations without matrix setup");
      data.maximum_newton_step =
        prm.get_double("Maximum allowable scaled length of the Newton step");
      data.dq_relative_error =
        prm.get_double("Relative error for different quotient computation");
      prm.leave_subsection();
      prm.leave_subsection();
    }


    KinsolSolver::KinsolSolver(const Parameters               &parameters,
                               const LinearSolver::Parameters &linear_solver)
      : parameters(parameters)
      , linear_solver(linear_solver)
    {
    }


    void
    KinsolSolver::solve(NonlinearProblem &problem,
                        Vector<double>   &u,
                        const double      load_factor,
                        const double      tolerance,
                        unsigned int     &iterations) const
    {
      const auto n       = problem.n_dofs();
      const auto targets = problem.prescribed_values(load_factor);

      auto data = parameters.data;
      if (data.function_tolerance == 0.)
        data.function_tolerance = tolerance;
      // a Jacobian per iteration unless the prm asks otherwise: the
      // tangent is exact, so this is Newton's method
      if (data.maximum_setup_calls == 0)
        data.maximum_setup_calls = 1;
      SUNDIALS::KINSOL<Vector<double>> kinsol(data);

      SparseMatrix<double> J;
      const LinearSolver   linear(linear_solver, problem.constant_modes());
      std::string          failure;

      kinsol.reinit_vector = [n](Vector<double> &v) { v.reinit(n); };
      kinsol.residual      = [&](const Vector<double> &x, Vector<double> &F) {
        Vector<double> y(x);
        if (problem.update_sparsity_pattern(y))
          J.reinit(problem.sparsity_pattern());
        if (!problem.assemble(y, load_factor, F, nullptr))
          return 1; // an inverted element: recoverable, shorter step
        for (const auto &t : targets)
          F[t.first] = x[t.first] - t.second;
        return std::isfinite(F.l2_norm()) ? 0 : 1;
      };
      kinsol.setup_jacobian = [&](const Vector<double> &x,
                                  const Vector<double> &) {
        if (problem.update_sparsity_pattern(x) || J.empty() || J.m() != n)
          J.reinit(problem.sparsity_pattern());
        Vector<double> R(n);
        if (!problem.assemble(x, load_factor, R, &J))
          return 1;
        // prescribed rows: identity
        for (const auto &t : targets)
          {
            for (auto it = J.begin(t.first); it != J.end(t.first); ++it)
              it->value() = 0.;
            J.set(t.first, t.first, 1.);
          }
        return 0;
      };
      kinsol.solve_with_jacobian =
        [&](const Vector<double> &rhs, Vector<double> &dst, const double) {
          try
            {
              dst = 0.;
              linear.solve(J, dst, rhs);
            }
          catch (const std::exception &e)
            {
              failure = error_message(e);
              return -1;
            }
          return 0;
        };

      try
        {
          iterations = kinsol.solve(u);
        }
      catch (const std::exception &e)
        {
          std::ostringstream s;
          s << "KINSOL did not converge"
            << (failure.empty() ? "" : " (" + failure + ")") << ": "
            << error_message(e);
          throw SolveFailed(s.str());
        }
    }
  } // namespace Solvers
} // namespace TissueContact
