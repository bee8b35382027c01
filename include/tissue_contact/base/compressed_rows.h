#pragma once

#include <deal.II/base/types.h>

#include <cstddef>
#include <vector>

namespace TissueContact
{
  using namespace dealii;

  /**
   * A sparse matrix's rows one after the other, without zeros: row i's
   * entries are rows_begin[i] ... rows_begin[i + 1] - 1 of @p column
   * (ascending) and @p value. The form the AMG hierarchy's transfers and
   * Galerkin products come in (solvers/amg_preconditioner.h); a level's
   * operator is taken from it without a SparsityPattern
   * (NonzeroMatrix::copy_from()).
   */
  struct CompressedRows
  {
    std::vector<std::size_t>             rows_begin;
    std::vector<types::global_dof_index> column;
    std::vector<double>                  value;
    unsigned int                         n_columns = 0;

    /** Rows. */
    types::global_dof_index
    n_rows() const
    {
      return rows_begin.empty() ? 0 : rows_begin.size() - 1;
    }
  };
} // namespace TissueContact
