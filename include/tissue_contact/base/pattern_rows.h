#pragma once

#include <deal.II/base/types.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <vector>

namespace TissueContact
{
  using namespace dealii;

  /**
   * A sparsity pattern while it is built: the columns of each row, sorted
   * and without duplicates. Its rows are independent vectors, so different
   * rows can be filled on different threads, and the finished pattern is
   * copied into a SparsityPattern at once (to_pattern()). The
   * contact pattern of the full knee is rebuilt some 400 times as the
   * contact zones move (doc/theory/05-contact.md sec. 7); built through
   * two DynamicSparsityPatterns, whose rows take columns one sorted
   * insertion at a time, it cost 105 ms per build on the knee's first 8
   * increments, and 77 ms with these rows.
   */
  using PatternRows = std::vector<std::vector<types::global_dof_index>>;

  /** The rows of the square @p pattern, each sorted (SparsityPattern stores
   * the diagonal first); the rows in parallel. */
  PatternRows
  rows_of(const SparsityPattern &pattern);

  /** Merge the sorted, duplicate-free @p columns into @p row (the same). */
  void
  merge_columns(std::vector<types::global_dof_index>       &row,
                const std::vector<types::global_dof_index> &columns);

  /** @p pattern = the square pattern of @p rows. */
  void
  to_pattern(const PatternRows &rows, SparsityPattern &pattern);
} // namespace TissueContact
