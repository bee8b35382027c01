#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/solvers/amg_preconditioner.h>

#include <deal.II/base/parallel.h>
#include <deal.II/lac/trilinos_precondition.h>

#include <Amesos.h>
#include <Epetra_MultiVector.h>
#include <Epetra_Vector.h>
#include <Teuchos_ParameterList.hpp>
#include <ml_MultiLevelPreconditioner.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <tuple>
#include <utility>

namespace TissueContact
{
  namespace Solvers
  {
    namespace
    {
      /** The entries of one of ML's operators (a level's matrix, a
       * prolongator or a restriction; one process: its local indices are
       * the global ones) without its zeros, each row sorted (ML's rows need
       * not be). */
      CompressedRows
      read_ml_operator(ML_Operator *op)
      {
        const int           m = op->outvec_leng;
        std::vector<int>    columns(128);
        std::vector<double> values(128);
        CompressedRows      rows;
        rows.n_columns = op->invec_leng;
        rows.rows_begin.push_back(0);
        std::vector<std::pair<types::global_dof_index, double>> row;
        for (int i = 0; i < m; ++i)
          {
            int row_index = i, length = 0;
            while (ML_Operator_Getrow(op,
                                      1,
                                      &row_index,
                                      columns.size(),
                                      columns.data(),
                                      values.data(),
                                      &length) == 0)
              {
                columns.resize(2 * columns.size());
                values.resize(2 * values.size());
              }
            row.clear();
            for (int k = 0; k < length; ++k)
              if (values[k] != 0.)
                row.emplace_back(columns[k], values[k]);
            std::sort(row.begin(), row.end());
            for (const auto &[j, v] : row)
              {
                rows.column.push_back(j);
                rows.value.push_back(v);
              }
            rows.rows_begin.push_back(rows.column.size());
          }
        return rows;
      }


      /** @p units = the rows of @p R six at a time, their columns
       * merged (an aggregate's rows under six near-null space vectors share
       * their columns): unit u's columns units.index[units.start[u]] ...
       * units.index[units.start[u + 1] - 1], ascending, each with the six
       * rows' values (zero where a row has none). */
      template <typename Units>
      void
      merge_rows_by_six(const CompressedRows &R, Units &units)
      {
        const unsigned int n = R.n_rows();
        units.start.assign(1, 0);
        units.index.clear();
        units.value.clear();
        std::vector<std::tuple<types::global_dof_index, unsigned int, double>>
          entries;
        for (unsigned int u = 0; 6 * u < n; ++u)
          {
            entries.clear();
            for (unsigned int r = 0; r < 6 && 6 * u + r < n; ++r)
              for (std::size_t q = R.rows_begin[6 * u + r];
                   q < R.rows_begin[6 * u + r + 1];
                   ++q)
                entries.emplace_back(R.column[q], r, R.value[q]);
            std::sort(entries.begin(), entries.end());
            for (std::size_t q = 0; q < entries.size();)
              {
                const auto            j = std::get<0>(entries[q]);
                std::array<double, 6> a{};
                for (; q < entries.size() && std::get<0>(entries[q]) == j; ++q)
                  a[std::get<1>(entries[q])] = std::get<2>(entries[q]);
                units.index.push_back(j);
                units.value.push_back(a);
              }
            units.start.push_back(units.index.size());
          }
      }


      /** @p blocks = the rows of @p P in blocks of six columns, a block
       * 6 K ... 6 K + 5 kept where the row has an entry in it. A row of plain
       * aggregation's tentative prolongator lies in one block, its
       * aggregate's coarse unknowns (one, three or six near-null space
       * vectors, numbered together); one of smoothed aggregation's reaches
       * a few neighbouring aggregates. */
      template <typename Sixes>
      void
      rows_by_blocks(const CompressedRows &P, Sixes &blocks)
      {
        blocks.start.assign(1, 0);
        blocks.index.clear();
        blocks.value.clear();
        for (types::global_dof_index i = 0; i < P.n_rows(); ++i)
          {
            // the row's columns ascend, so do its blocks
            for (std::size_t q = P.rows_begin[i]; q < P.rows_begin[i + 1];)
              {
                const types::global_dof_index K = P.column[q] / 6;
                std::array<double, 6>         v{};
                for (; q < P.rows_begin[i + 1] && P.column[q] / 6 == K; ++q)
                  v[P.column[q] % 6] = P.value[q];
                blocks.index.push_back(K);
                blocks.value.push_back(v);
              }
            blocks.start.push_back(blocks.index.size());
          }
      }


      /** @p y = P @p x for P's rows in blocks of six columns
       * (rows_by_blocks()), on the threads: each row summed from zero over
       * its columns in ascending order as SparseMatrix::vmult() does (a zero
       * of a block adds a zero, which changes no sum), the same to the
       * bit. */
      template <typename Sixes>
      void
      prolongate(const Sixes &P, Vector<double> &y, const Vector<double> &x)
      {
        parallel::apply_to_subranges(
          types::global_dof_index(0),
          types::global_dof_index(y.size()),
          [&](const types::global_dof_index begin,
              const types::global_dof_index end) {
            for (types::global_dof_index i = begin; i < end; ++i)
              {
                double s = 0.;
                for (std::size_t q = P.start[i]; q < P.start[i + 1]; ++q)
                  {
                    // the last block may reach past x's end (a coarse
                    // level of 6 k + 1 ... 5 unknowns); its entries there
                    // are zero and not read
                    const types::global_dof_index first = 6 * P.index[q];
                    const unsigned int            width =
                      std::min<types::global_dof_index>(6, x.size() - first);
                    const double *xK = x.begin() + first;
                    const auto   &v  = P.value[q];
                    for (unsigned int c = 0; c < width; ++c)
                      s += v[c] * xK[c];
                  }
                y[i] = s;
              }
          },
          1000);
      }


      /** @p y = R @p x for R's rows six at a time (merge_rows_by_six()),
       * on the threads: each row summed as SparseMatrix::vmult() does, the
       * same to the bit. */
      template <typename Sixes>
      void
      restrict_to(const Sixes &R, Vector<double> &y, const Vector<double> &x)
      {
        const types::global_dof_index n = y.size();
        parallel::apply_to_subranges(
          types::global_dof_index(0),
          types::global_dof_index(R.start.size() - 1),
          [&](const types::global_dof_index begin,
              const types::global_dof_index end) {
            for (types::global_dof_index u = begin; u < end; ++u)
              {
                std::array<double, 6> s{};
                for (std::size_t q = R.start[u]; q < R.start[u + 1]; ++q)
                  {
                    const double xj = x[R.index[q]];
                    for (unsigned int r = 0; r < 6; ++r)
                      s[r] += R.value[q][r] * xj;
                  }
                for (unsigned int r = 0; r < 6 && 6 * u + r < n; ++r)
                  y[6 * u + r] = s[r];
              }
          },
          100);
      }


      /** The product A @p B without the zeros of either, B's rows in
       * blocks of six columns (rows_by_blocks()), of its @p n columns'
       * @p n / 6 blocks (rounded up), on the threads, where A's m rows come
       * in units of @p rows_per_unit consecutive rows (the last may be cut
       * short at m): @p entries(u, f, f3) calls f(j, a) for the unit's
       * entries, a[r] the entry in column j of its row r, or f3(j, a0, a1,
       * a2) for columns j, j + 1, j + 2 in turn. A unit's rows share B's
       * rows, read once for all of them. The product's rows come in blocks
       * of six, a block kept where one of its entries is not zero. Each
       * entry is summed in the order @p entries gives, whatever the number
       * of threads; a zero of B's blocks adds a zero, which changes no sum,
       * so the entries are those of the product with B's nonzeros alone to
       * the bit, for one look-up of a block where that makes one per
       * column. */
      template <unsigned int rows_per_unit, typename Entries, typename Sixes>
      Sixes
      block_product(const unsigned int m,
                    const unsigned int n,
                    const Entries     &entries,
                    const Sixes       &B)
      {
        using Block                = std::array<double, 6>;
        const unsigned int n_b     = (n + 5) / 6;
        const unsigned int n_units = (m + rows_per_unit - 1) / rows_per_unit;
        // the units in parts, each part's rows gathered on its own and put
        // one after the other at the end
        const unsigned int n_parts = std::min(64u, std::max(1u, n_units / 32));
        const auto         first_row = [&](const unsigned int part) {
          return std::min<unsigned int>(m,
                                        rows_per_unit * (std::size_t(part) *
                                                         n_units / n_parts));
        };
        std::vector<Sixes>       part(n_parts);
        std::vector<std::size_t> row_length(m);
        parallel::apply_to_subranges(
          0u,
          n_parts,
          [&](const unsigned int first, const unsigned int last) {
            // the unit's rows of the product, dense by block, and the
            // blocks met
            std::vector<std::array<Block, rows_per_unit>> sum(n_b);
            std::vector<unsigned int>                     seen(n_b, 0);
            std::vector<types::global_dof_index>          blocks;
            unsigned int                                  stamp = 0;
            for (unsigned int p = first; p < last; ++p)
              for (unsigned int u = first_row(p) / rows_per_unit;
                   rows_per_unit * u < first_row(p + 1);
                   ++u)
                {
                  ++stamp;
                  blocks.clear();
                  // block K of the unit's rows, zeroed when first met
                  const auto block_of = [&](const types::global_dof_index K)
                    -> std::array<Block, rows_per_unit> & {
                    if (seen[K] != stamp)
                      {
                        seen[K] = stamp;
                        for (Block &row : sum[K])
                          row.fill(0.);
                        blocks.push_back(K);
                      }
                    return sum[K];
                  };
                  // column j's entries a of the unit's rows: a (x) B's row j
                  const auto add =
                    [&](const types::global_dof_index            j,
                        const std::array<double, rows_per_unit> &a) {
                      for (std::size_t q = B.start[j]; q < B.start[j + 1]; ++q)
                        {
                          auto        &s = block_of(B.index[q]);
                          const Block &b = B.value[q];
                          for (unsigned int r = 0; r < rows_per_unit; ++r)
                            for (unsigned int c = 0; c < 6; ++c)
                              s[r][c] += a[r] * b[c];
                        }
                    };
                  // columns j, j + 1, j + 2 one after the other; where B's
                  // three rows have the same blocks (a vertex's three
                  // unknowns: one block, their aggregate's, in a tentative
                  // prolongator; the same blocks of coarse columns in A P)
                  // each sum takes the three terms in turn while it is at
                  // hand: the same additions in the same order as three
                  // calls of add()
                  const auto add_three =
                    [&](const types::global_dof_index            j,
                        const std::array<double, rows_per_unit> &a0,
                        const std::array<double, rows_per_unit> &a1,
                        const std::array<double, rows_per_unit> &a2) {
                      const std::size_t q0 = B.start[j];
                      const std::size_t l  = B.start[j + 1] - q0;
                      if (B.start[j + 2] - B.start[j + 1] == l &&
                          B.start[j + 3] - B.start[j + 2] == l &&
                          std::equal(B.index.begin() + q0,
                                     B.index.begin() + q0 + l,
                                     B.index.begin() + q0 + l) &&
                          std::equal(B.index.begin() + q0,
                                     B.index.begin() + q0 + l,
                                     B.index.begin() + q0 + 2 * l))
                        for (std::size_t q = q0; q < q0 + l; ++q)
                          {
                            auto        &s  = block_of(B.index[q]);
                            const Block &b0 = B.value[q];
                            const Block &b1 = B.value[q + l];
                            const Block &b2 = B.value[q + 2 * l];
                            for (unsigned int r = 0; r < rows_per_unit; ++r)
                              for (unsigned int c = 0; c < 6; ++c)
                                {
                                  double t = s[r][c];
                                  t += a0[r] * b0[c];
                                  t += a1[r] * b1[c];
                                  t += a2[r] * b2[c];
                                  s[r][c] = t;
                                }
                          }
                      else
                        {
                          add(j, a0);
                          add(j + 1, a1);
                          add(j + 2, a2);
                        }
                    };
                  entries(u, add, add_three);
                  std::sort(blocks.begin(), blocks.end());
                  for (unsigned int r = 0;
                       r < rows_per_unit && rows_per_unit * u + r < m;
                       ++r)
                    {
                      std::size_t length = 0;
                      for (const auto K : blocks)
                        if (std::any_of(sum[K][r].begin(),
                                        sum[K][r].end(),
                                        [](const double v) { return v != 0.; }))
                          {
                            part[p].index.push_back(K);
                            part[p].value.push_back(sum[K][r]);
                            ++length;
                          }
                      row_length[rows_per_unit * u + r] = length;
                    }
                }
          },
          1);
        Sixes product;
        product.start.resize(m + 1);
        product.start[0] = 0;
        for (unsigned int i = 0; i < m; ++i)
          product.start[i + 1] = product.start[i] + row_length[i];
        product.index.resize(product.start[m]);
        product.value.resize(product.start[m]);
        for (unsigned int p = 0; p < n_parts; ++p)
          {
            const std::size_t start = product.start[first_row(p)];
            std::copy(part[p].index.begin(),
                      part[p].index.end(),
                      product.index.begin() + start);
            std::copy(part[p].value.begin(),
                      part[p].value.end(),
                      product.value.begin() + start);
          }
        return product;
      }


      /** The entries @p first ... @p last - 1 of a row (or unit) whose
       * columns @p column(k) ascend, in order: @p three(k) for entries k,
       * k + 1, k + 2 in columns j, j + 1, j + 2, else @p one(k). */
      template <typename Column, typename One, typename Three>
      void
      by_threes(const std::size_t first,
                const std::size_t last,
                const Column     &column,
                const One        &one,
                const Three      &three)
      {
        for (std::size_t k = first; k < last;)
          if (k + 2 < last && column(k + 2) == column(k) + 2)
            {
              three(k);
              k += 3;
            }
          else
            {
              one(k);
              ++k;
            }
      }


      /** The Galerkin product R @p A P (A's nonzeros, in groups of three
       * rows) on a coarse level of @p n_c unknowns (R's rows, P's columns),
       * with R's rows six at a time as merge_rows_by_six() gives them in
       * @p R and P's rows in blocks of six in @p P. */
      template <typename Sixes>
      CompressedRows
      galerkin_product(const Sixes         &R,
                       const NonzeroMatrix &A,
                       const Sixes         &P,
                       const unsigned int   n_c)
      {
        const unsigned int m = A.m();
        // A's entries of the vertex g's three rows: the three diagonals,
        // then the other columns ascending
        const auto A_entries =
          [&](const types::global_dof_index g, const auto &f, const auto &f3) {
            for (unsigned int r = 0; r < 3 && 3 * g + r < m; ++r)
              {
                std::array<double, 3> a{};
                a[r] = A.diag_element(3 * g + r);
                f(3 * g + r, a);
              }
            const auto entry = [&](const std::size_t k) {
              const double *v = A.values_of(k);
              return std::array<double, 3>{{v[0], v[1], v[2]}};
            };
            // a vertex's three columns together where all three are kept
            by_threes(
              A.group_begin(g),
              A.group_end(g),
              [&](const std::size_t k) { return A.column_of(k); },
              [&](const std::size_t k) { f(A.column_of(k), entry(k)); },
              [&](const std::size_t k) {
                f3(A.column_of(k), entry(k), entry(k + 1), entry(k + 2));
              });
          };
        const auto R_entries =
          [&](const types::global_dof_index u, const auto &f, const auto &f3) {
            by_threes(
              R.start[u],
              R.start[u + 1],
              [&](const std::size_t q) { return R.index[q]; },
              [&](const std::size_t q) { f(R.index[q], R.value[q]); },
              [&](const std::size_t q) {
                f3(R.index[q], R.value[q], R.value[q + 1], R.value[q + 2]);
              });
          };
        const Sixes AP  = block_product<3>(m, n_c, A_entries, P);
        const Sixes RAP = block_product<6>(n_c, n_c, R_entries, AP);
        // the blocks' nonzeros as rows
        CompressedRows product;
        product.n_columns = n_c;
        product.rows_begin.reserve(n_c + 1);
        product.rows_begin.assign(1, 0);
        product.column.reserve(6 * RAP.index.size());
        product.value.reserve(6 * RAP.index.size());
        for (unsigned int i = 0; i < n_c; ++i)
          {
            for (std::size_t q = RAP.start[i]; q < RAP.start[i + 1]; ++q)
              for (unsigned int c = 0; c < 6; ++c)
                if (RAP.value[q][c] != 0.)
                  {
                    product.column.push_back(6 * RAP.index[q] + c);
                    product.value.push_back(RAP.value[q][c]);
                  }
            product.rows_begin.push_back(product.column.size());
          }
        return product;
      }

      /** An Epetra matrix for ML (one process) of @p n rows, written row
       * by row in one pass: @p for_each_nonzero(i, f) calls f(j, a) for
       * row i's nonzeros. */
      template <typename ForEachNonzero>
      std::unique_ptr<Epetra_CrsMatrix>
      epetra_matrix(const int             n,
                    const Epetra_Map     &map,
                    const ForEachNonzero &for_each_nonzero)
      {
        std::vector<int> length(n, 0);
        for (int i = 0; i < n; ++i)
          for_each_nonzero(i, [&](int, double) { ++length[i]; });
        auto matrix = std::make_unique<Epetra_CrsMatrix>(
          Copy, map, map, length.data(), true);
        std::vector<int>    column;
        std::vector<double> value;
        for (int i = 0; i < n; ++i)
          {
            column.clear();
            value.clear();
            for_each_nonzero(i, [&](const int j, const double a) {
              column.push_back(j);
              value.push_back(a);
            });
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


      /** The nonzeros of @p A as an Epetra matrix for ML: ML's own copy
       * through TrilinosWrappers::SparseMatrix took 44 ms per tangent of
       * the full knee, and the copy of the nonzeros before it 31 ms. */
      std::unique_ptr<Epetra_CrsMatrix>
      epetra_nonzeros(const SparseMatrix<double> &A, const Epetra_Map &map)
      {
        // a square SparseMatrix stores a row's values one after the other
        // from its diagonal's on (base/nonzero_matrix.h)
        const SparsityPattern &pattern = A.get_sparsity_pattern();
        return epetra_matrix(A.m(), map, [&](const int i, const auto &f) {
          const double *a = &A(i, i);
          for (unsigned int k = 0; k < pattern.row_length(i); ++k)
            if (a[k] != 0.)
              f(pattern.column_number(i, k), a[k]);
        });
      }


      /** The entries of @p A as an Epetra matrix. */
      std::unique_ptr<Epetra_CrsMatrix>
      epetra_nonzeros(const CompressedRows &A, const Epetra_Map &map)
      {
        return epetra_matrix(A.n_rows(), map, [&](const int i, const auto &f) {
          for (std::size_t k = A.rows_begin[i]; k < A.rows_begin[i + 1]; ++k)
            f(A.column[k], A.value[k]);
        });
      }
    } // namespace


    void
    AMGPreconditioner::initialize(const SparseMatrix<double> &A,
                                  const std::vector<double>  &null_space,
                                  const unsigned int null_space_dimension,
                                  const bool         smoothed_aggregation)
    {
      grids.clear();
      operators[0].clear();
      operators[1].clear();
      current  = 0;
      accepted = -1;
      n_rows   = A.m();
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

      for (unsigned int l = 0; l < n; ++l)
        {
          grids.push_back(std::make_unique<Grid>());
          operators[0].push_back(std::make_unique<Level>());
        }
      for (unsigned int l = 0; l < n; ++l)
        {
          Grid &grid = *grids[l];
          // the finest level's nonzeros from A itself, the coarser ones
          // from ML's Galerkin products
          const unsigned int rows_above = l > 0 ? grids[l - 1]->b.size() : 0;
          CompressedRows     level_matrix;
          if (l > 0)
            {
              level_matrix = read_ml_operator(&ml_levels->Amat[l]);
              const CompressedRows P_rows =
                read_ml_operator(&ml_levels->Pmat[l]);
              const CompressedRows R_rows =
                read_ml_operator(&ml_levels->Rmat[l - 1]);
              AssertThrow(P_rows.n_rows() == rows_above &&
                            P_rows.n_columns == level_matrix.n_rows() &&
                            R_rows.n_rows() == level_matrix.n_rows() &&
                            R_rows.n_columns == rows_above,
                          ExcMessage("ML's transfers do not match its "
                                     "levels' sizes"));
              merge_rows_by_six(R_rows, grid.R_units);
              rows_by_blocks(P_rows, grid.P_blocks);
            }
          const unsigned int rows = l > 0 ? level_matrix.n_rows() : A.m();
          grid.b.reinit(rows);
          grid.x.reinit(rows);
          grid.residual.reinit(rows);
          grid.correction.reinit(rows);
          if (l > 0)
            set_operator(operators[0], l, level_matrix);
          else
            set_operator(operators[0], l, A);
        }
    }


    void
    AMGPreconditioner::refresh(
      const SparseMatrix<double>                 &A,
      const std::shared_ptr<const NonzeroMatrix> &A_nonzeros)
    {
      AssertThrow(!grids.empty() && A.m() == m(),
                  ExcMessage("an AMG hierarchy refreshed with a matrix of "
                             "another size"));
      // into the set that is not the accepted one
      const unsigned int target =
        accepted < 0 ? current : 1 - static_cast<unsigned int>(accepted);
      Operators &set = operators[target];
      while (set.size() < grids.size())
        set.push_back(std::make_unique<Level>());
      // the current set until the new one is complete (a singular coarse
      // operator throws on the way)
      current = accepted < 0 ? current : static_cast<unsigned int>(accepted);
      // each level's operator from the one above: A_l = R_l A_{l-1} P_l
      set_operator(set, 0, A, A_nonzeros);
      for (unsigned int l = 1; l < grids.size(); ++l)
        {
          set_operator(set,
                       l,
                       galerkin_product(grids[l]->R_units,
                                        *set[l - 1]->A,
                                        grids[l]->P_blocks,
                                        grids[l]->b.size()));
        }
      current = target;
    }


    const NonzeroMatrix *
    AMGPreconditioner::accepted_finest() const
    {
      return accepted < 0 || operators[accepted].empty() ?
               nullptr :
               operators[accepted][0]->A.get();
    }


    void
    AMGPreconditioner::accept()
    {
      accepted = current;
    }


    bool
    AMGPreconditioner::restore()
    {
      if (accepted < 0 || static_cast<unsigned int>(accepted) == current)
        return false;
      current = accepted;
      return true;
    }


    void
    AMGPreconditioner::set_operator(
      Operators                                  &set,
      const unsigned int                          l,
      const SparseMatrix<double>                 &matrix,
      const std::shared_ptr<const NonzeroMatrix> &nonzeros)
    {
      Assert(l == 0, ExcInternalError());
      Level &level = *set[l];
      if (grids.size() == 1)
        // a single level: its factorization
        factorize(level, matrix.m(), [&](const Epetra_Map &map) {
          return epetra_nonzeros(matrix, map);
        });
      // the smoother lets go of the operator before it is replaced
      level.smoother.clear();
      if (nonzeros)
        level.A = nonzeros;
      else
        {
          auto own = std::make_shared<NonzeroMatrix>();
          own->copy_from(matrix);
          level.A = std::move(own);
        }
      set_smoother(level);
    }


    void
    AMGPreconditioner::set_operator(Operators            &set,
                                    const unsigned int    l,
                                    const CompressedRows &matrix)
    {
      Assert(l > 0, ExcInternalError());
      Level &level = *set[l];
      if (l + 1 == grids.size())
        factorize(level, matrix.n_rows(), [&](const Epetra_Map &map) {
          return epetra_nonzeros(matrix, map);
        });
      else
        {
          level.smoother.clear();
          auto own = std::make_shared<NonzeroMatrix>();
          own->copy_from(matrix);
          level.A = std::move(own);
          set_smoother(level);
        }
    }


    void
    AMGPreconditioner::factorize(
      Level             &level,
      const unsigned int n,
      const std::function<std::unique_ptr<Epetra_CrsMatrix>(const Epetra_Map &)>
        &make_matrix)
    {
      // its LU factorization by KLU, as ML's (a refreshed one's
      // factorization, problem and matrix go before the map and
      // communicator they were made with)
      level.direct.reset();
      level.problem.reset();
      level.matrix.reset();
      level.comm = std::make_unique<Epetra_MpiComm>(MPI_COMM_SELF);
      level.map =
        std::make_unique<Epetra_Map>(static_cast<int>(n), 0, *level.comm);
      level.matrix  = make_matrix(*level.map);
      level.problem = std::make_unique<Epetra_LinearProblem>();
      level.problem->SetOperator(level.matrix.get());
      level.direct.reset(Amesos().Create("Amesos_Klu", *level.problem));
      // a singular coarse operator fails the step like a solve that does
      // not converge: the increment is cut back
      if (!(level.direct && level.direct->SymbolicFactorization() == 0 &&
            level.direct->NumericFactorization() == 0))
        throw SolveFailed("KLU could not factorize the coarsest level of "
                          "the AMG hierarchy (a singular coarse operator); "
                          "try Linear solver/Type = direct");
    }


    void
    AMGPreconditioner::set_smoother(Level &level)
    {
      // Chebyshev of degree 2 on the Jacobi-scaled operator over
      // [lambda_max / 10, lambda_max] (ML's "smoother: Chebyshev alpha" =
      // 10). The scaling by |a_ii| and the power iteration keep the
      // smoother finite on the indefinite tangents of deep contact (rows
      // with a_ii < 0), where a Lanczos estimate with the signed diagonal
      // returned NaN on tangents of the full knee
      Smoother::AdditionalData data;
      data.degree              = 2;
      data.smoothing_range     = 10.;
      data.eig_cg_n_iterations = 10;
      data.eigenvalue_algorithm =
        Smoother::AdditionalData::EigenvalueAlgorithm::power_iteration;
      data.preconditioner = std::make_shared<DiagonalMatrix<Vector<double>>>();
      Vector<double> &inverse_diagonal = data.preconditioner->get_vector();
      inverse_diagonal.reinit(level.A->m());
      for (types::global_dof_index i = 0; i < level.A->m(); ++i)
        {
          const double a      = std::abs(level.A->diag_element(i));
          inverse_diagonal[i] = (a > 0. && std::isfinite(a)) ? 1. / a : 1.;
        }
      level.smoother.initialize(*level.A, data);
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
      const Level &level = *operators[current][l];
      const Grid  &grid  = *grids[l];
      if (l > 0 && l + 1 == grids.size())
        {
          solve_coarsest(level, x, b);
          return;
        }
      // x_1 = S b
      level.smoother.vmult(x, b);
      // x_2 = x_1 + C (b - A x_1)
      level.A->residual(grid.residual, x, b);
      if (l + 1 == grids.size())
        // a single level: its factorization
        solve_coarsest(level, grid.correction, grid.residual);
      else
        {
          const Grid &coarse = *grids[l + 1];
          restrict_to(coarse.R_units, coarse.b, grid.residual);
          cycle(l + 1, coarse.x, coarse.b);
          prolongate(coarse.P_blocks, grid.correction, coarse.x);
        }
      x += grid.correction;
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
