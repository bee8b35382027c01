#include <tissue_contact/base/nonzero_matrix.h>

#include <deal.II/base/parallel.h>

#include <algorithm>
#include <array>

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


  void
  NonzeroMatrix::copy_from(const SparseMatrix<double> &A)
  {
    AssertDimension(A.m(), A.n());
    const types::global_dof_index n       = A.m();
    const types::global_dof_index groups  = (n + 2) / 3;
    const SparsityPattern        &pattern = A.get_sparsity_pattern();
    // a square SparseMatrix stores each row's values one after the other,
    // its diagonal first: the row's values are read from the diagonal's
    // address on, which is 2.7 times faster than through the matrix's
    // iterators (1.5 against 4.2 ms for both passes on a tangent of the
    // full knee, two threads)
    const auto row_values = [&](const types::global_dof_index i) {
      return &A(i, i);
    };
    // the union of a group's off-diagonal nonzero columns, ascending: the
    // three rows' sorted lists merged, f(column, row, value) for each entry
    // (f(column, 3, 0) once per column before its entries)
    const auto merge = [&](const types::global_dof_index g, const auto &f) {
      const unsigned int rows = std::min<types::global_dof_index>(3, n - 3 * g);
      std::array<const double *, 3>            v{};
      std::array<SparsityPattern::iterator, 3> entry{
        {pattern.end(0), pattern.end(0), pattern.end(0)}};
      std::array<unsigned int, 3> j{}, length{};
      for (unsigned int c = 0; c < rows; ++c)
        {
          const types::global_dof_index i = 3 * g + c;
          v[c]                            = row_values(i);
          length[c]                       = pattern.row_length(i);
          entry[c]                        = pattern.begin(i);
          ++entry[c];
          j[c] = 1;
        }
      // the next nonzero of row c (or the end)
      const auto skip_zeros = [&](const unsigned int c) {
        while (j[c] < length[c] && v[c][j[c]] == 0.)
          {
            ++j[c];
            ++entry[c];
          }
      };
      for (unsigned int c = 0; c < rows; ++c)
        skip_zeros(c);
      for (;;)
        {
          types::global_dof_index next = numbers::invalid_dof_index;
          for (unsigned int c = 0; c < rows; ++c)
            if (j[c] < length[c])
              next = std::min(next, entry[c]->column());
          if (next == numbers::invalid_dof_index)
            return;
          f(next, 3u, 0.);
          for (unsigned int c = 0; c < rows; ++c)
            if (j[c] < length[c] && entry[c]->column() == next)
              {
                f(next, c, v[c][j[c]]);
                ++j[c];
                ++entry[c];
                skip_zeros(c);
              }
        }
    };
    // pass 1: each group's column count, in group_start[g + 1]; then their
    // sums
    group_start.assign(groups + 1, 0);
    std::vector<std::size_t> entries(groups, 0);
    for_each_row(groups, [&](const types::global_dof_index g) {
      std::size_t columns = 0;
      merge(g, [&](types::global_dof_index, const unsigned int c, double) {
        if (c == 3)
          ++columns;
        else
          ++entries[g];
      });
      group_start[g + 1] = columns;
    });
    n_nonzeros = n;
    for (types::global_dof_index g = 0; g < groups; ++g)
      {
        group_start[g + 1] += group_start[g];
        n_nonzeros += entries[g];
      }
    // pass 2: the columns and values; a row's own diagonal among the
    // columns stays zero (its term comes first, from diagonal[])
    column.resize(group_start[groups]);
    value.assign(3 * group_start[groups], 0.);
    diagonal.resize(n);
    for_each_row(groups, [&](const types::global_dof_index g) {
      for (unsigned int c = 0; c < 3 && 3 * g + c < n; ++c)
        diagonal[3 * g + c] = *row_values(3 * g + c);
      std::size_t k = group_start[g];
      merge(g,
            [&](const types::global_dof_index j,
                const unsigned int            c,
                const double                  a) {
              if (c == 3)
                column[k++] = j;
              else
                value[3 * (k - 1) + c] = a;
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


  void
  NonzeroMatrix::vmult(Vector<double> &y, const Vector<double> &x) const
  {
    AssertDimension(x.size(), m());
    AssertDimension(y.size(), m());
    const types::global_dof_index n = m();
    for_each_row(group_start.size() - 1, [&](const types::global_dof_index g) {
      const types::global_dof_index i = 3 * g;
      // a missing row (the last group of a matrix of 3 k + 1 or 2 rows)
      // reads row i's diagonal and x and is not written
      const types::global_dof_index i1 = std::min(i + 1, n - 1),
                                    i2 = std::min(i + 2, n - 1);
      double s0 = 0., s1 = 0., s2 = 0.;
      s0 += diagonal[i] * x[i];
      s1 += diagonal[i1] * x[i1];
      s2 += diagonal[i2] * x[i2];
      const double *v = value.data() + 3 * group_start[g];
      for (std::size_t k = group_start[g]; k < group_start[g + 1]; ++k, v += 3)
        {
          const double xk = x[column[k]];
          s0 += v[0] * xk;
          s1 += v[1] * xk;
          s2 += v[2] * xk;
        }
      y[i] = s0;
      if (i + 1 < n)
        y[i + 1] = s1;
      if (i + 2 < n)
        y[i + 2] = s2;
    });
  }


  void
  NonzeroMatrix::residual(Vector<double>       &r,
                          const Vector<double> &x,
                          const Vector<double> &b) const
  {
    AssertDimension(x.size(), m());
    AssertDimension(b.size(), m());
    AssertDimension(r.size(), m());
    const types::global_dof_index n = m();
    for_each_row(group_start.size() - 1, [&](const types::global_dof_index g) {
      const types::global_dof_index i  = 3 * g;
      const types::global_dof_index i1 = std::min(i + 1, n - 1),
                                    i2 = std::min(i + 2, n - 1);
      double s0 = b[i], s1 = b[i1], s2 = b[i2];
      s0 -= diagonal[i] * x[i];
      s1 -= diagonal[i1] * x[i1];
      s2 -= diagonal[i2] * x[i2];
      const double *v = value.data() + 3 * group_start[g];
      for (std::size_t k = group_start[g]; k < group_start[g + 1]; ++k, v += 3)
        {
          const double xk = x[column[k]];
          s0 -= v[0] * xk;
          s1 -= v[1] * xk;
          s2 -= v[2] * xk;
        }
      r[i] = s0;
      if (i + 1 < n)
        r[i + 1] = s1;
      if (i + 2 < n)
        r[i + 2] = s2;
    });
  }
} // namespace TissueContact
