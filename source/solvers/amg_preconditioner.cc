#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/solvers/amg_preconditioner.h>

#include <deal.II/lac/trilinos_precondition.h>

#include <Amesos.h>
#include <Epetra_MultiVector.h>
#include <Epetra_Vector.h>
#include <Teuchos_ParameterList.hpp>
#include <ml_MultiLevelPreconditioner.h>

#include <cmath>
#include <memory>

namespace TissueContact
{
  namespace Solvers
  {
    namespace
    {
      /** The entries of one of ML's operators (a level's matrix, a
       * prolongator or a restriction; one process: its local indices are
       * the global ones) as a deal.II matrix, without its zeros. */
      void
      read_ml_operator(ML_Operator          *op,
                       SparsityPattern      &pattern,
                       SparseMatrix<double> &matrix)
      {
        const int                 m = op->outvec_leng, n = op->invec_leng;
        std::vector<int>          columns(128);
        std::vector<double>       values(128);
        std::vector<unsigned int> row_length(m);
        std::vector<types::global_dof_index> column;
        std::vector<double>                  value;
        for (int i = 0; i < m; ++i)
          {
            int row = i, length = 0;
            while (ML_Operator_Getrow(op,
                                      1,
                                      &row,
                                      columns.size(),
                                      columns.data(),
                                      values.data(),
                                      &length) == 0)
              {
                columns.resize(2 * columns.size());
                values.resize(2 * values.size());
              }
            for (int k = 0; k < length; ++k)
              if (values[k] != 0.)
                {
                  column.push_back(columns[k]);
                  value.push_back(values[k]);
                  ++row_length[i];
                }
          }
        // a square pattern stores each row's diagonal, present or not
        std::vector<unsigned int> capacity(row_length);
        if (m == n)
          for (unsigned int &c : capacity)
            ++c;
        pattern.reinit(m, n, capacity);
        std::size_t k = 0;
        for (int i = 0; i < m; k += row_length[i], ++i)
          pattern.add_entries(i,
                              column.begin() + k,
                              column.begin() + k + row_length[i]);
        pattern.compress();
        matrix.reinit(pattern);
        k = 0;
        for (int i = 0; i < m; k += row_length[i], ++i)
          matrix.set(i, row_length[i], column.data() + k, value.data() + k);
      }

      /** The nonzeros of @p A as an Epetra matrix for ML (one process),
       * written row by row in one pass: ML's own copy through
       * TrilinosWrappers::SparseMatrix took 44 ms per tangent of the full
       * knee, and the copy of the nonzeros before it 31 ms. */
      std::unique_ptr<Epetra_CrsMatrix>
      epetra_nonzeros(const SparseMatrix<double> &A, const Epetra_Map &map)
      {
        // a square SparseMatrix stores a row's values one after the other
        // from its diagonal's on (base/nonzero_matrix.h)
        const SparsityPattern &pattern = A.get_sparsity_pattern();
        const int              n       = A.m();
        std::vector<int>       length(n, 0);
        for (int i = 0; i < n; ++i)
          {
            const double *a = &A(i, i);
            for (unsigned int k = 0; k < pattern.row_length(i); ++k)
              length[i] += (a[k] != 0.);
          }
        auto matrix = std::make_unique<Epetra_CrsMatrix>(
          Copy, map, map, length.data(), true);
        std::vector<int>    column;
        std::vector<double> value;
        for (int i = 0; i < n; ++i)
          {
            column.clear();
            value.clear();
            const double *a = &A(i, i);
            for (unsigned int k = 0; k < pattern.row_length(i); ++k)
              if (a[k] != 0.)
                {
                  column.push_back(pattern.column_number(i, k));
                  value.push_back(a[k]);
                }
            const int error = matrix->InsertMyValues(i,
                                                     column.size(),
                                                     value.data(),
                                                     column.data());
            AssertThrow(error == 0,
                        ExcMessage("Epetra could not take a row of the "
                                   "matrix"));
          }
        matrix->FillComplete(map, map);
        return matrix;
      }
    } // namespace


    void
    AMGPreconditioner::initialize(const SparseMatrix<double> &A,
                                  const std::vector<double>  &null_space,
                                  const unsigned int null_space_dimension,
                                  const bool         smoothed_aggregation)
    {
      levels.clear();
      // ML's hierarchy of the nonzeros (doc/theory/04-solver.md
      // sec. 4.5.2), with the project's settings; its smoothers and coarse
      // solver are the cycle's below, not ML's
      const Epetra_MpiComm comm(MPI_COMM_SELF);
      const Epetra_Map     map(static_cast<int>(A.m()), 0, comm);
      const std::unique_ptr<Epetra_CrsMatrix> ml_matrix =
        epetra_nonzeros(A, map);
      TrilinosWrappers::PreconditionAMG::AdditionalData amg_data;
      amg_data.elliptic              = true;
      amg_data.higher_order_elements = false;
      amg_data.smoother_sweeps       = 2;
      amg_data.aggregation_threshold = 1e-4;
      Teuchos::ParameterList              ml;
      std::unique_ptr<Epetra_MultiVector> unused;
      amg_data.set_parameters(ml, unused, *ml_matrix);
      ml.set("smoother: type", "do-nothing");
      ml.set("coarse: type", "do-nothing");
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
      TrilinosWrappers::PreconditionAMG hierarchy;
      hierarchy.initialize(*ml_matrix, ml);
      const ML *ml_levels =
        dynamic_cast<const ML_Epetra::MultiLevelPreconditioner &>(
          hierarchy.trilinos_operator())
          .GetML();
      AssertThrow(ml_levels != nullptr && ml_levels->ML_finest_level == 0,
                  ExcMessage("ML's hierarchy is not numbered from the "
                             "finest level up"));
      const unsigned int n = ml_levels->ML_num_actual_levels;

      // each level's operator, transfers and smoother: Chebyshev of degree
      // 2 on the Jacobi-scaled matrix over [lambda_max / 10, lambda_max]
      // (ML's "smoother: Chebyshev alpha" = 10). The scaling by |a_ii| and
      // the power iteration keep the smoother finite on the indefinite
      // tangents of deep contact (rows with a_ii < 0), where a Lanczos
      // estimate with the signed diagonal returned NaN on tangents of the
      // full knee
      const auto make_smoother = [](Level &level) {
        Smoother::AdditionalData data;
        data.degree              = 2;
        data.smoothing_range     = 10.;
        data.eig_cg_n_iterations = 10;
        data.eigenvalue_algorithm =
          Smoother::AdditionalData::EigenvalueAlgorithm::power_iteration;
        data.preconditioner =
          std::make_shared<DiagonalMatrix<Vector<double>>>();
        Vector<double> &inverse_diagonal = data.preconditioner->get_vector();
        inverse_diagonal.reinit(level.A.m());
        for (types::global_dof_index i = 0; i < level.A.m(); ++i)
          {
            const double a      = std::abs(level.A.diag_element(i));
            inverse_diagonal[i] = (a > 0. && std::isfinite(a)) ? 1. / a : 1.;
          }
        level.smoother.initialize(level.A, data);
      };
      for (unsigned int l = 0; l < n; ++l)
        {
          levels.push_back(std::make_unique<Level>());
          Level &level = *levels.back();
          // the finest level's nonzeros from A itself, the coarser ones
          // from ML's Galerkin products
          SparsityPattern      level_pattern;
          SparseMatrix<double> level_matrix;
          if (l > 0)
            {
              read_ml_operator(&ml_levels->Amat[l],
                               level_pattern,
                               level_matrix);
              read_ml_operator(&ml_levels->Pmat[l], level.P_pattern, level.P);
              read_ml_operator(&ml_levels->Rmat[l - 1],
                               level.R_pattern,
                               level.R);
              AssertThrow(level.P.m() == levels[l - 1]->A.m() &&
                            level.P.n() == level_matrix.m() &&
                            level.R.m() == level_matrix.m() &&
                            level.R.n() == levels[l - 1]->A.m(),
                          ExcMessage("ML's transfers do not match its "
                                     "levels' sizes"));
            }
          const SparseMatrix<double> &matrix = l > 0 ? level_matrix : A;
          if (l + 1 == n)
            {
              // the coarsest level: its LU factorization by KLU, as ML's
              level.comm = std::make_unique<Epetra_MpiComm>(MPI_COMM_SELF);
              level.map =
                std::make_unique<Epetra_Map>(static_cast<int>(matrix.m()),
                                             0,
                                             *level.comm);
              level.matrix  = epetra_nonzeros(matrix, *level.map);
              level.problem = std::make_unique<Epetra_LinearProblem>();
              level.problem->SetOperator(level.matrix.get());
              level.direct.reset(Amesos().Create("Amesos_Klu", *level.problem));
              // a singular coarse operator fails the step like a solve
              // that does not converge: the increment is cut back
              if (!(level.direct &&
                    level.direct->SymbolicFactorization() == 0 &&
                    level.direct->NumericFactorization() == 0))
                throw SolveFailed("KLU could not factorize the coarsest "
                                  "level of the AMG hierarchy (a singular "
                                  "coarse operator); try Linear solver/Type "
                                  "= direct");
            }
          if (l == 0 || l + 1 < n)
            {
              // the finest level from A itself, whose rows have the block
              // layout the copy reads fastest (base/nonzero_matrix.h)
              level.A.copy_from(l > 0 ? matrix : A);
              make_smoother(level);
              level.residual.reinit(level.A.m());
              level.correction.reinit(level.A.m());
            }
          if (l > 0)
            {
              level.b.reinit(matrix.m());
              level.x.reinit(matrix.m());
            }
        }
    }


    void
    AMGPreconditioner::solve_coarsest(const Level          &level,
                                      Vector<double>       &x,
                                      const Vector<double> &b)
    {
      Epetra_Vector X(View, *level.map, x.data());
      Epetra_Vector B(View, *level.map, const_cast<double *>(b.data()));
      level.problem->SetLHS(&X);
      level.problem->SetRHS(&B);
      if (level.direct->Solve() != 0)
        throw SolveFailed("KLU could not solve on the coarsest level of the "
                          "AMG hierarchy; try Linear solver/Type = direct");
    }


    void
    AMGPreconditioner::cycle(const unsigned int    l,
                             Vector<double>       &x,
                             const Vector<double> &b) const
    {
      const Level &level = *levels[l];
      if (l > 0 && l + 1 == levels.size())
        {
          solve_coarsest(level, x, b);
          return;
        }
      // x_1 = S b
      level.smoother.vmult(x, b);
      // x_2 = x_1 + C (b - A x_1)
      level.A.residual(level.residual, x, b);
      if (l + 1 == levels.size())
        // a single level: its factorization
        solve_coarsest(level, level.correction, level.residual);
      else
        {
          const Level &coarse = *levels[l + 1];
          coarse.R.vmult(coarse.b, level.residual);
          cycle(l + 1, coarse.x, coarse.b);
          coarse.P.vmult(level.correction, coarse.x);
        }
      x += level.correction;
      // x = x_2 + S (b - A x_2)
      level.smoother.step(x, b);
    }


    void
    AMGPreconditioner::vmult(Vector<double> &x, const Vector<double> &b) const
    {
      cycle(0, x, b);
    }
  } // namespace Solvers
} // namespace TissueContact
