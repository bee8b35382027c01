#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/base/parameter_tools.h>
#include <tissue_contact/solvers/kinsol_solver.h>

#include <deal.II/lac/sparse_matrix.h>

#include <sstream>

namespace TissueContact
{
  namespace Solvers
  {
    void
    KinsolSolver::Parameters::declare_parameters(ParameterHandler &prm)
    {
      using Data = SUNDIALS::KINSOL<Vector<double>>::AdditionalData;
      prm.enter_subsection("KINSOL");
      add_selection<Data::SolutionStrategy>(
        prm,
        "Solution strategy",
        data.strategy,
        {{"newton", Data::newton},
         {"linesearch", Data::linesearch},
         {"fixed_point", Data::fixed_point},
         {"picard", Data::picard}},
        "KINSOL's method: newton (full Newton steps), linesearch (Newton "
        "with KINSOL's backtracking line search), fixed_point or picard "
        "(with Anderson acceleration; slow on stiff elasticity).");
      prm.add_parameter("Maximum number of nonlinear iterations",
                        data.maximum_non_linear_iterations,
                        "KINSOL's iterations per load increment or time step "
                        "before it gives up (>= 1).",
                        Patterns::Integer(1));
      prm.add_parameter("Function norm stopping tolerance",
                        data.function_tolerance,
                        "Converged when the largest residual entry on the "
                        "free DoFs is below this (force units, >= 0); 0: "
                        "Residual tolerance times the force scale, like "
                        "the project's Newton.",
                        Patterns::Double(0.));
      prm.add_parameter("Scaled step stopping tolerance",
                        data.step_tolerance,
                        "KINSOL also stops when the scaled step is below "
                        "this (length units, >= 0; 0: KINSOL's default).",
                        Patterns::Double(0.));
      prm.enter_subsection("Fixed point and Picard parameters");
      prm.add_parameter("Anderson acceleration subspace size",
                        data.anderson_subspace_size,
                        "Vectors kept by Anderson acceleration of the "
                        "fixed_point and picard strategies (>= 0; 0: none).",
                        Patterns::Integer(0));
      prm.leave_subsection();
      prm.enter_subsection("Linesearch parameters");
      prm.add_parameter("Maximum number of beta-condition failures",
                        data.maximum_beta_failures,
                        "Line-search steps failing KINSOL's beta condition "
                        "allowed per solve (>= 0; 0: KINSOL's default).",
                        Patterns::Integer(0));
      prm.leave_subsection();
      prm.enter_subsection("Newton parameters");
      prm.add_parameter("No initial matrix setup",
                        data.no_init_setup,
                        "Start from the tangent of the previous solve "
                        "instead of assembling one (true: cheaper, may "
                        "converge slower).",
                        Patterns::Bool());
      prm.add_parameter("Maximum iterations without matrix setup",
                        data.maximum_setup_calls,
                        "Reassemble the tangent every this many iterations "
                        "(>= 0; 0 here means 1: a tangent per iteration, "
                        "exact Newton).",
                        Patterns::Integer(0));
      prm.add_parameter("Maximum allowable scaled length of the Newton step",
                        data.maximum_newton_step,
                        "KINSOL shortens longer Newton steps (length units, "
                        ">= 0; 0: KINSOL's default, 1000 times the initial "
                        "guess's norm).",
                        Patterns::Double(0.));
      prm.add_parameter("Relative error for different quotient computation",
                        data.dq_relative_error,
                        "Used only by KINSOL's difference-quotient "
                        "Jacobian, which the project never uses (it "
                        "supplies the exact tangent); >= 0.",
                        Patterns::Double(0.));
      prm.leave_subsection();
      prm.leave_subsection();
    }


    KinsolSolver::KinsolSolver(const Parameters               &parameters,
                               const LinearSolver::Parameters &linear_solver)
      : parameters(parameters)
      , linear_solver(linear_solver)
    {}


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
      const auto           resolved =
        linear_solver.resolved(n, problem.pattern_widening());
      const LinearSolver linear(resolved,
                                resolved.uses_near_null_space() ?
                                  problem.near_null_space() :
                                  std::vector<Vector<double>>());
      std::string        failure;

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
      // KINSOL also returns "success" when its scaled step falls below the
      // step tolerance, wherever that happens: accept only a state without
      // inverted elements whose residual meets the tolerance
      Vector<double> R(n);
      if (!problem.assemble(u, load_factor, R, nullptr))
        throw SolveFailed("KINSOL stopped at a state with an inverted element "
                          "(its scaled step fell below the Scaled step "
                          "stopping tolerance there)");
      for (const auto &t : targets)
        R[t.first] = u[t.first] - t.second;
      if (!(R.linfty_norm() <= data.function_tolerance))
        {
          std::ostringstream s;
          s << "KINSOL stopped without converging: its scaled step fell below "
               "the Scaled step stopping tolerance with max |R| = "
            << R.linfty_norm() << " above the tolerance "
            << data.function_tolerance
            << " (lower Scaled step stopping tolerance, or use Nonlinear "
               "solver = Newton)";
          throw SolveFailed(s.str());
        }
    }
  } // namespace Solvers
} // namespace TissueContact
