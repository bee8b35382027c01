#include <tissue_contact/base/nonzero_matrix.h>

#include <deal.II/base/parallel.h>

namespace TissueContact
{
  namespace
  {
    /** @p f(i) for the rows i of an @p n-row matrix, on the threads, 500
     * rows per task (a row holds about 30-70 entries on the full knee). */
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
    const SparsityPattern        &pattern = A.get_sparsity_pattern();
    // a square SparseMatrix stores each row's values one after the other,
    // its diagonal first: the row's values are read from the diagonal's
    // address on, which is 2.7 times faster than through the matrix's
    // iterators (1.5 against 4.2 ms for both passes on a tangent of the
    // full knee, two threads)
    const auto row_values = [&](const types::global_dof_index i) {
      return &A(i, i);
    };
    // pass 1: each row's count, in row_start[i + 1]; then their sums
    row_start.assign(n + 1, 0);
    for_each_row(n, [&](const types::global_dof_index i) {
      const double      *v      = row_values(i);
      const unsigned int length = pattern.row_length(i);
      std::size_t        count  = 1; // the diagonal, always
      for (unsigned int k = 1; k < length; ++k)
        count += (v[k] != 0.);
      row_start[i + 1] = count;
    });
    for (types::global_dof_index i = 0; i < n; ++i)
      row_start[i + 1] += row_start[i];
    // pass 2: the entries, in each row's order
    column.resize(row_start[n]);
    value.resize(row_start[n]);
    for_each_row(n, [&](const types::global_dof_index i) {
      const double      *v      = row_values(i);
      const unsigned int length = pattern.row_length(i);
      std::size_t        k      = row_start[i];
      column[k]                 = i;
      value[k]                  = v[0];
      ++k;
      auto entry = pattern.begin(i);
      ++entry;
      for (unsigned int j = 1; j < length; ++j, ++entry)
        if (v[j] != 0.)
          {
            column[k] = entry->column();
            value[k]  = v[j];
            ++k;
          }
    });
  }


  void
  NonzeroMatrix::vmult(Vector<double> &y, const Vector<double> &x) const
  {
    AssertDimension(x.size(), m());
    AssertDimension(y.size(), m());
    for_each_row(m(), [&](const types::global_dof_index i) {
      double s = 0.;
      for (std::size_t k = row_start[i]; k < row_start[i + 1]; ++k)
        s += value[k] * x[column[k]];
      y[i] = s;
    });
  }
} // namespace TissueContact
