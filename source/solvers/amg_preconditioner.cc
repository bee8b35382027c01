#include <tissue_contact/base/nonzero_copy.h>
#include <tissue_contact/solvers/amg_preconditioner.h>

#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>

#include <cmath>
#include <memory>

namespace TissueContact
{
  namespace Solvers
  {
    void
    AMGPreconditioner::initialize(const SparseMatrix<double> &A,
                                  const std::vector<double>  &null_space,
                                  const unsigned int null_space_dimension,
                                  const bool         smoothed_aggregation)
    {
      // the copy first (the smoother and the hierarchy keep references),
      // without the entries that are stored but zero (doc/theory/
      // 04-solver.md sec. 4.5.2)
      {
        SparsityPattern      pattern;
        SparseMatrix<double> matrix;
        copy_nonzeros(A, pattern, matrix);
        ml_matrix.reinit(matrix);
      }
      finest.copy_from(A);

      // the project's ML settings, with nothing done on the finest level
      // (ML skips that level's residual too: its initial guess is zero)
      TrilinosWrappers::PreconditionAMG::AdditionalData amg_data;
      amg_data.elliptic              = true;
      amg_data.higher_order_elements = false;
      amg_data.smoother_sweeps       = 2;
      amg_data.aggregation_threshold = 1e-4;
      Teuchos::ParameterList              ml;
      std::unique_ptr<Epetra_MultiVector> unused;
      amg_data.set_parameters(ml, unused, ml_matrix);
      ml.set("smoother: type (level 0)", "do-nothing");
      if (!smoothed_aggregation)
        ml.set("aggregation: damping factor", 0.);
      if (null_space_dimension > 0)
        {
          AssertDimension(null_space.size(), null_space_dimension * A.m());
          // given as vectors: AdditionalData takes only 0/1 masks
          ml.set("null space: type", "pre-computed");
          ml.set("null space: dimension",
                 static_cast<int>(null_space_dimension));
          ml.set("null space: vectors",
                 const_cast<double *>(null_space.data()));
        }
      coarse_levels.initialize(ml_matrix, ml);

      // the finest level's smoother as ML's: Chebyshev of degree 2 on the
      // Jacobi-scaled matrix over [lambda_max / 10, lambda_max] (ML's
      // "smoother: Chebyshev alpha" = 10). The scaling by |a_ii| and the
      // power iteration keep the smoother finite on the indefinite tangents
      // of deep contact (rows with a_ii < 0), where a Lanczos estimate
      // with the signed diagonal returned NaN on tangents of the full knee
      Smoother::AdditionalData data;
      data.degree              = 2;
      data.smoothing_range     = 10.;
      data.eig_cg_n_iterations = 10;
      data.eigenvalue_algorithm =
        Smoother::AdditionalData::EigenvalueAlgorithm::power_iteration;
      data.preconditioner = std::make_shared<DiagonalMatrix<Vector<double>>>();
      Vector<double> &inverse_diagonal = data.preconditioner->get_vector();
      inverse_diagonal.reinit(finest.m());
      for (types::global_dof_index i = 0; i < finest.m(); ++i)
        {
          const double a      = std::abs(finest.diag_element(i));
          inverse_diagonal[i] = (a > 0. && std::isfinite(a)) ? 1. / a : 1.;
        }
      smoother.initialize(finest, data);
      residual.reinit(finest.m());
      correction.reinit(finest.m());
    }


    void
    AMGPreconditioner::vmult(Vector<double> &x, const Vector<double> &b) const
    {
      // x_1 = S b
      smoother.vmult(x, b);
      // x_2 = x_1 + C (b - A x_1)
      finest.residual(residual, x, b);
      coarse_levels.vmult(correction, residual);
      x += correction;
      // x = x_2 + S (b - A x_2)
      smoother.step(x, b);
    }
  } // namespace Solvers
} // namespace TissueContact
