#include <tissue_contact/base/nonzero_matrix.h>

#include <deal.II/base/parallel.h>

#include <algorithm>
#include <array>
#include <tuple>
#include <utility>

namespace TissueContact
{
  namespace
  {
    /** @p f(i) for i = 0 ... @p n - 1 (rows or groups of three rows), on
     * the threads, 500 per task (a row holds about 30-70 entries on the
     * full knee). */
    template <typename F>
    void
    for_each_row(const types::global_dof_index n, const F &f)
    {
      parallel::apply_to_subranges(
        types::global_dof_index(0),
        n,
        [&](const types::global_dof_index begin,
            const types::global_dof_index end) {
          for (types::global_dof_index i = begin; i < end; ++i)
            f(i);
        },
        500);
    }
  } // namespace


  template <typename Count>
  void
  NonzeroMatrix::size_groups(const types::global_dof_index n,
                             const Count                  &count)
  {
    const types::global_dof_index groups = (n + 2) / 3;
    std::vector<std::size_t>      entries(groups, 0);
    group_start.assign(groups + 1, 0);
    for_each_row(groups, [&](const types::global_dof_index g) {
      std::tie(group_start[g + 1], entries[g]) = count(g);
    });
    n_nonzeros = n;
    for (types::global_dof_index g = 0; g < groups; ++g)
      {
        group_start[g + 1] += group_start[g];
        n_nonzeros += entries[g];
      }
    column.resize(group_start[groups]);
    value.resize(3 * group_start[groups]);
    diagonal.resize(n);
  }


  void
  NonzeroMatrix::copy_from(const SparseMatrix<double> &A)
  {
    AssertDimension(A.m(), A.n());
    const types::global_dof_index n       = A.m();
    const types::global_dof_index groups  = (n + 2) / 3;
    const SparsityPattern        &pattern = A.get_sparsity_pattern();
    Assert(pattern.is_compressed(), ExcNotInitialized());
    // a square SparseMatrix stores each row's values one after the other,
    // its diagonal first: the row's values are read from the diagonal's
    // address on, which is 2.7 times faster than through the matrix's
    // iterators (1.5 against 4.2 ms for both passes on a tangent of the
    // full knee, two threads)
    const auto row_values = [&](const types::global_dof_index i) {
      return &A(i, i);
    };
    const auto column_of = [&](const types::global_dof_index i,
                               const unsigned int            k) {
      return pattern.column_number(i, k);
    };
    // the layout of a vertex's three rows as deal.II's patterns of
    // vector-valued elements and the contact couplings (whole 3 x 3 blocks)
    // store them: the same columns, each row's own diagonal first. Row 0's
    // other columns are then those of rows 1 and 2 but at the two positions
    // p + 1, p + 2 after the p columns below i = 3 g, where row 0 has
    // i + 1, i + 2, row 1 i, i + 2 and row 2 i, i + 1. Returns p, or
    // invalid if the rows are laid out otherwise
    constexpr unsigned int other = numbers::invalid_unsigned_int;
    const auto             block_layout =
      [&](const types::global_dof_index g) -> unsigned int {
      const types::global_dof_index i = 3 * g;
      if (i + 2 >= n)
        return other;
      const unsigned int length = pattern.row_length(i);
      if (pattern.row_length(i + 1) != length ||
          pattern.row_length(i + 2) != length)
        return other;
      unsigned int p = 0;
      while (1 + p < length && column_of(i, 1 + p) < i)
        ++p;
      if (!(p + 2 < length && column_of(i, 1 + p) == i + 1 &&
            column_of(i, 2 + p) == i + 2 && column_of(i + 1, 1 + p) == i &&
            column_of(i + 1, 2 + p) == i + 2 && column_of(i + 2, 1 + p) == i &&
            column_of(i + 2, 2 + p) == i + 1))
        return other;
      for (unsigned int k = 1; k < length; ++k)
        if (k != 1 + p && k != 2 + p &&
            (column_of(i + 1, k) != column_of(i, k) ||
             column_of(i + 2, k) != column_of(i, k)))
          return other;
      return p;
    };
    // f(j, a) for the columns j of the rows of group g laid out as
    // above (p), ascending, with a[c] row 3 g + c's entry there (zero at
    // its own diagonal), whether zero or not
    const auto for_each_block_column = [&](const types::global_dof_index g,
                                           const unsigned int            p,
                                           const auto                   &f) {
      const types::global_dof_index i      = 3 * g;
      const unsigned int            length = pattern.row_length(i);
      const double                 *v0 = row_values(i), *v1 = row_values(i + 1),
                   *v2 = row_values(i + 2);
      for (unsigned int k = 1; k <= p; ++k)
        f(column_of(i, k), v0[k], v1[k], v2[k]);
      f(i, 0., v1[1 + p], v2[1 + p]);
      f(i + 1, v0[1 + p], 0., v2[2 + p]);
      f(i + 2, v0[2 + p], v1[2 + p], 0.);
      for (unsigned int k = 3 + p; k < length; ++k)
        f(column_of(i, k), v0[k], v1[k], v2[k]);
    };
    // the same for rows laid out otherwise, only the nonzero columns: their
    // lists merged
    const auto for_each_merged_column = [&](const types::global_dof_index g,
                                            const auto                   &f) {
      const types::global_dof_index i = 3 * g;
      const unsigned int rows = std::min<types::global_dof_index>(3, n - i);
      std::array<const double *, 3> v{};
      std::array<unsigned int, 3>   length{}, k{{1, 1, 1}};
      for (unsigned int c = 0; c < rows; ++c)
        {
          v[c]      = row_values(i + c);
          length[c] = pattern.row_length(i + c);
        }
      const auto skip_zeros = [&](const unsigned int c) {
        while (k[c] < length[c] && v[c][k[c]] == 0.)
          ++k[c];
      };
      for (unsigned int c = 0; c < rows; ++c)
        skip_zeros(c);
      for (;;)
        {
          types::global_dof_index next = numbers::invalid_dof_index;
          for (unsigned int c = 0; c < rows; ++c)
            if (k[c] < length[c])
              next = std::min(next, column_of(i + c, k[c]));
          if (next == numbers::invalid_dof_index)
            return;
          std::array<double, 3> a{{0., 0., 0.}};
          for (unsigned int c = 0; c < rows; ++c)
            if (k[c] < length[c] && column_of(i + c, k[c]) == next)
              {
                a[c] = v[c][k[c]];
                ++k[c];
                skip_zeros(c);
              }
          f(next, a[0], a[1], a[2]);
        }
    };
    // pass 1: each group's layout, and the count of its columns with a
    // nonzero (in group_start[g + 1]; then their sums) and of its nonzeros.
    // Counted without branches on the values: which entries are zero
    // follows no pattern a branch predictor could learn
    std::vector<unsigned int> layout(groups);
    size_groups(n, [&](const types::global_dof_index g) {
      layout[g]            = block_layout(g);
      std::size_t columns  = 0;
      std::size_t nonzeros = 0;
      const auto  count    = [&](types::global_dof_index,
                             const double a0,
                             const double a1,
                             const double a2) {
        const std::size_t z = (a0 != 0.) + (a1 != 0.) + (a2 != 0.);
        columns += (z != 0);
        nonzeros += z;
      };
      if (layout[g] != other)
        for_each_block_column(g, layout[g], count);
      else
        for_each_merged_column(g, count);
      return std::make_pair(columns, nonzeros);
    });
    // pass 2: the columns and values, each written and kept (the position
    // advanced) only if it has a nonzero, again without a branch on the
    // values; a row's own diagonal among the columns stays zero (its term
    // comes first, from diagonal[])
    for_each_row(groups, [&](const types::global_dof_index g) {
      for (unsigned int c = 0; c < 3 && 3 * g + c < n; ++c)
        diagonal[3 * g + c] = *row_values(3 * g + c);
      std::size_t       k     = group_start[g];
      const std::size_t end   = group_start[g + 1];
      const auto        write = [&](const types::global_dof_index j,
                             const double                  a0,
                             const double                  a1,
                             const double                  a2) {
        if (k == end)
          return; // the columns left have no nonzero
        column[k]        = j;
        value[3 * k]     = a0;
        value[3 * k + 1] = a1;
        value[3 * k + 2] = a2;
        k += (a0 != 0. || a1 != 0. || a2 != 0.);
      };
      if (layout[g] != other)
        for_each_block_column(g, layout[g], write);
      else
        for_each_merged_column(g, write);
    });
  }


  void
  NonzeroMatrix::copy_from(const CompressedRows &A)
  {
    const types::global_dof_index n = A.n_rows();
    AssertDimension(n, A.n_columns);
    const types::global_dof_index groups = (n + 2) / 3;
    // f(j, a) for the columns j of group g's rows other than each row's
    // own diagonal, ascending, with a[c] row 3 g + c's entry there (zero
    // where it has none): the rows' sorted lists merged, their zeros
    // skipped, as a SparseMatrix of these entries is read
    const auto for_each_column = [&](const types::global_dof_index g,
                                     const auto                   &f) {
      const types::global_dof_index i = 3 * g;
      const unsigned int rows = std::min<types::global_dof_index>(3, n - i);
      std::array<std::size_t, 3> k{}, end{};
      const auto                 next_entry = [&](const unsigned int c) {
        while (k[c] < end[c] &&
               (A.value[k[c]] == 0. || A.column[k[c]] == i + c))
          ++k[c];
      };
      for (unsigned int c = 0; c < rows; ++c)
        {
          k[c]   = A.rows_begin[i + c];
          end[c] = A.rows_begin[i + c + 1];
          next_entry(c);
        }
      for (;;)
        {
          types::global_dof_index next = numbers::invalid_dof_index;
          for (unsigned int c = 0; c < rows; ++c)
            if (k[c] < end[c])
              next = std::min(next, A.column[k[c]]);
          if (next == numbers::invalid_dof_index)
            return;
          std::array<double, 3> a{{0., 0., 0.}};
          for (unsigned int c = 0; c < rows; ++c)
            if (k[c] < end[c] && A.column[k[c]] == next)
              {
                a[c] = A.value[k[c]];
                ++k[c];
                next_entry(c);
              }
          f(next, a);
        }
    };
    // pass 1: the count of each group's columns (in group_start[g + 1];
    // then their sums) and of its nonzeros
    size_groups(n, [&](const types::global_dof_index g) {
      std::size_t columns = 0, nonzeros = 0;
      for_each_column(g,
                      [&](types::global_dof_index,
                          const std::array<double, 3> &a) {
                        ++columns;
                        nonzeros += (a[0] != 0.) + (a[1] != 0.) + (a[2] != 0.);
                      });
      return std::make_pair(columns, nonzeros);
    });
    // pass 2: the diagonals (zero where a row stores none), the columns and
    // values
    for_each_row(groups, [&](const types::global_dof_index g) {
      for (types::global_dof_index i = 3 * g; i < std::min(3 * g + 3, n); ++i)
        {
          const auto begin = A.column.begin() + A.rows_begin[i],
                     end   = A.column.begin() + A.rows_begin[i + 1];
          const auto at    = std::lower_bound(begin, end, i);
          diagonal[i] =
            (at != end && *at == i) ? A.value[at - A.column.begin()] : 0.;
        }
      std::size_t k = group_start[g];
      for_each_column(g,
                      [&](const types::global_dof_index j,
                          const std::array<double, 3>  &a) {
                        column[k] = j;
                        for (unsigned int c = 0; c < 3; ++c)
                          value[3 * k + c] = a[c];
                        ++k;
                      });
    });
  }


  double
  NonzeroMatrix::el(const types::global_dof_index i,
                    const types::global_dof_index j) const
  {
    AssertIndexRange(i, m());
    AssertIndexRange(j, n());
    if (i == j)
      return diagonal[i];
    const types::global_dof_index g     = i / 3;
    const auto                    begin = column.begin() + group_start[g],
               end                      = column.begin() + group_start[g + 1];
    const auto at                       = std::lower_bound(begin, end, j);
    return (at != end && *at == j) ? value[3 * (at - column.begin()) + i % 3] :
                                     0.;
  }


  template <bool residual>
  void
  NonzeroMatrix::products(Vector<double>       &y,
                          const Vector<double> &x,
                          const Vector<double> *b) const
  {
    const types::global_dof_index n  = m();
    const double *const           xv = x.begin();
    double *const                 yv = y.begin();
    const double *const           bv = residual ? b->begin() : nullptr;
    const double *const           d  = diagonal.data();
    // row i's sum begun as SparseMatrix::vmult() and residual() begin it:
    // 0 + a_ii x_i, or b_i - a_ii x_i; then a term added or subtracted
    const auto first = [&](const types::global_dof_index i) {
      double s = residual ? bv[i] : 0.;
      if (residual)
        s -= d[i] * xv[i];
      else
        s += d[i] * xv[i];
      return s;
    };
    const auto add = [](double &s, const double a, const double xk) {
      if (residual)
        s -= a * xk;
      else
        s += a * xk;
    };
    // the groups' loop written out in each range, on raw arrays: called
    // per group through for_each_row(), the group's function was not
    // inlined (a product on 31 944 DoFs, one thread: 0.35 -> 0.30 ms)
    const std::size_t *const             start = group_start.data();
    const types::global_dof_index *const cols  = column.data();
    const double *const                  vals  = value.data();
    parallel::apply_to_subranges(
      types::global_dof_index(0),
      types::global_dof_index(group_start.size() - 1),
      [&](const types::global_dof_index begin,
          const types::global_dof_index end) {
        for (types::global_dof_index g = begin; g < end; ++g)
          {
            const types::global_dof_index i = 3 * g;
            // a missing row (the last group of a matrix of 3 k + 1 or 2
            // rows) reads row i's diagonal and x and is not written
            const types::global_dof_index i1 = std::min(i + 1, n - 1),
                                          i2 = std::min(i + 2, n - 1);
            double        s0 = first(i), s1 = first(i1), s2 = first(i2);
            const double *v = vals + 3 * start[g];
            for (std::size_t k = start[g]; k < start[g + 1]; ++k, v += 3)
              {
                const double xk = xv[cols[k]];
                add(s0, v[0], xk);
                add(s1, v[1], xk);
                add(s2, v[2], xk);
              }
            yv[i] = s0;
            if (i + 1 < n)
              yv[i + 1] = s1;
            if (i + 2 < n)
              yv[i + 2] = s2;
          }
      },
      500);
  }


  void
  NonzeroMatrix::vmult(Vector<double> &y, const Vector<double> &x) const
  {
    AssertDimension(x.size(), m());
    AssertDimension(y.size(), m());
    products<false>(y, x, nullptr);
  }


  void
  NonzeroMatrix::residual(Vector<double>       &r,
                          const Vector<double> &x,
                          const Vector<double> &b) const
  {
    AssertDimension(x.size(), m());
    AssertDimension(b.size(), m());
    AssertDimension(r.size(), m());
    products<true>(r, x, &b);
  }
} // namespace TissueContact
