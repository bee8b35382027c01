#include <tissue_contact/base/nonzero_copy.h>

#include <vector>

namespace TissueContact
{
  void
  copy_nonzeros(const SparseMatrix<double> &A,
                SparsityPattern            &pattern,
                SparseMatrix<double>       &copy)
  {
    AssertDimension(A.m(), A.n());
    const types::global_dof_index n = A.m();
    // (the row passed in: an iterator's row() is a search in deal.II)
    const auto kept = [](const auto &entry, const types::global_dof_index i) {
      return entry.value() != 0. || entry.column() == i;
    };
    // the kept columns row by row, written into the pattern's arrays at
    // once (SparsityPattern::copy_from() of rows; adding them entry by entry
    // took 60 products' time on a tangent of the full knee)
    std::vector<std::vector<types::global_dof_index>> rows(n);
    for (types::global_dof_index i = 0; i < n; ++i)
      for (auto entry = A.begin(i); entry != A.end(i); ++entry)
        if (kept(*entry, i))
          rows[i].push_back(entry->column());
    copy.clear();
    pattern.copy_from(n, n, rows.begin(), rows.end());
    copy.reinit(pattern);
    // both store a row's diagonal first, then its columns in increasing
    // order: the kept entries of A are the copy's, one after the other
    for (types::global_dof_index i = 0; i < n; ++i)
      {
        auto to = copy.begin(i);
        for (auto entry = A.begin(i); entry != A.end(i); ++entry)
          if (kept(*entry, i))
            {
              Assert(to->column() == entry->column(), ExcInternalError());
              to->value() = entry->value();
              ++to;
            }
      }
  }
} // namespace TissueContact
