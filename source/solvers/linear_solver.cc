#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/solvers/linear_solver.h>

#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

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
      prm.add_parameter(
        "Direct solver",
        direct_solver,
        "For Type = direct: UMFPACK (deal.II's SparseDirectUMFPACK) or MUMPS "
        "(the multifrontal solver through Trilinos Amesos: the same solution "
        "to rounding, 1.1-1.9 times faster on the meshes measured in "
        "doc/theory/04-solver.md sec. 4.5; a tangent it cannot factorize "
        "cuts the increment back).",
        Patterns::Selection("UMFPACK|MUMPS"));
      prm.add_parameter(
        "AMG rotations",
        amg_rotations,
        "For Type = GMRES+AMG: false, the near-null space is the three "
        "translations; true, the six rigid-body modes (translations and "
        "rotations). Measured on a clamped 27 783-unknown P1 cube: half the "
        "GMRES iterations at 1e-8 (29 instead of 57), three times the "
        "hierarchy's setup (2.5 s instead of 0.7 s per solve).",
        Patterns::Bool());
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
      if (parameters.type == "direct" && parameters.direct_solver == "MUMPS")
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
      else if (parameters.type == "direct")
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
                  TrilinosWrappers::PreconditionAMG amg;
                  // the fine level of the hierarchy keeps a reference to A
                  TrilinosWrappers::SparseMatrix A;
                  if (null_space_dimension == 0)
                    amg.initialize(K, amg_data);
                  else
                    {
                      // deal.II's ML settings, with the null space given
                      // as vectors (AdditionalData takes only 0/1 masks)
                      AssertDimension(null_space.size(),
                                      null_space_dimension * K.m());
                      A.reinit(K);
                      Teuchos::ParameterList              ml;
                      std::unique_ptr<Epetra_MultiVector> unused;
                      amg_data.set_parameters(ml, unused, A);
                      ml.set("null space: type", "pre-computed");
                      ml.set("null space: dimension",
                             static_cast<int>(null_space_dimension));
                      ml.set("null space: vectors",
                             const_cast<double *>(null_space.data()));
                      amg.initialize(A, ml);
                    }
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
