#pragma once

#include <deal.II/base/types.h>

#include <cstddef>
#include <vector>

namespace TissueContact
{
  using namespace dealii;

  /** The number of ranges to split rows into: one per thread
   * (MultithreadInfo::n_threads()), at most 64. */
  unsigned int
  n_row_ranges();

  /**
   * Split rows 0..n into @p n_parts ranges of about equal work for threads
   * that each own the rows of one range: a loop over elements (or contact
   * pairs) in a fixed order in which every thread adds only to its own rows
   * gives every entry the same additions in the same order as the serial
   * loop, so the sums are the same to the last bit on any number of
   * threads, and no two threads write the same row.
   *
   * @p work holds n + 1 numbers, the running sum of the rows' work:
   * work[r + 1] - work[r] is row r's (for instance the number of elements
   * with an unknown in that row). Returns the n_parts + 1 bounds
   * b_0 = 0 <= b_1 <= ... <= b_P = n; range p is [b_p, b_{p+1}), and b_p is
   * the first row with at least p / P of the total work before it.
   */
  std::vector<types::global_dof_index>
  balanced_row_ranges(const std::vector<std::size_t> &work,
                      const unsigned int              n_parts);
} // namespace TissueContact
