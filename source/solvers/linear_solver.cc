#include <tissue_contact/solvers/linear_solver.h>

#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/trilinos_precondition.h>

namespace TissueContact
{
  namespace Solvers
  {
    void
    LinearSolver::Parameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      prm.add_parameter(
        "Type",
        type,
        "Linear solver of each Newton step: GMRES+Jacobi (inexact GMRES "
        "with diagonal preconditioning, dissertation 4.7.3), direct (sparse "
        "LU, UMFPACK) or GMRES+AMG (Trilinos ML algebraic multigrid).",
        Patterns::Selection("GMRES+Jacobi|direct|GMRES+AMG"));
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
      const Parameters                     &parameters,
      const std::vector<std::vector<bool>> &constant_modes)
      : parameters(parameters)
      , constant_modes(constant_modes)
    {
      AssertThrow(parameters.type == "GMRES+Jacobi" ||
                    parameters.type == "direct" ||
                    parameters.type == "GMRES+AMG",
                  ExcMessage("Linear solver: unknown Type '" + parameters.type +
                             "'; use GMRES+Jacobi, direct or GMRES+AMG"));
    }


    unsigned int
    LinearSolver::solve(const SparseMatrix<double> &K,
                        Vector<double>             &x,
                        const Vector<double>       &b) const
    {
      unsigned int iterations = 1;
      x                       = 0.;
      if (parameters.type == "direct")
        {
          SparseDirectUMFPACK lu;
          lu.initialize(K);
          lu.vmult(x, b);
        }
      else
        {
          ReductionControl control(parameters.max_iterations,
                                   1e-300,
                                   parameters.relative_tolerance,
                                   false,
                                   false);
          SolverGMRES<Vector<double>>::AdditionalData data;
          data.max_n_tmp_vectors = 52;
          SolverGMRES<Vector<double>> gmres(control, data);
          try
            {
              if (parameters.type == "GMRES+Jacobi")
                {
                  PreconditionJacobi<SparseMatrix<double>> jacobi;
                  jacobi.initialize(K);
                  gmres.solve(K, x, b, jacobi);
                }
              else
                {
                  TrilinosWrappers::PreconditionAMG::AdditionalData amg_data;
                  amg_data.elliptic              = true;
                  amg_data.higher_order_elements = false;
                  amg_data.smoother_sweeps       = 2;
                  amg_data.aggregation_threshold = 1e-4;
                  amg_data.constant_modes        = constant_modes;
                  TrilinosWrappers::PreconditionAMG amg;
                  amg.initialize(K, amg_data);
                  gmres.solve(K, x, b, amg);
                }
            }
          catch (const SolverControl::NoConvergence &)
            {
              // inexact Newton: the iterate after the cap is used as is
            }
          iterations = control.last_step();
        }
      AssertThrow(std::isfinite(x.l2_norm()),
                  ExcMessage("the linear solver (" + parameters.type +
                             ") produced a non-finite Newton update; the "
                             "tangent matrix is singular or ill-conditioned"));
      return iterations;
    }
  } // namespace Solvers
} // namespace TissueContact
