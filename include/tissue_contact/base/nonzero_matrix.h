#pragma once

#include <deal.II/base/types.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <cstddef>
#include <vector>

namespace TissueContact
{
  using namespace dealii;

  /**
   * The nonzero entries of a square SparseMatrix in compressed rows, taken
   * anew from each matrix, and their product: the operator GMRES multiplies
   * with (doc/theory/04-solver.md sec. 4.5.2).
   *
   * The tangent of a contact scene stores many zeros: the zeroed rows and
   * columns of prescribed DoFs and the couplings of contact candidates not
   * in contact. On a tangent of the full knee that is 61 % of 2.08 million
   * stored entries, and a product with the tangent costs 2.5 products with
   * its nonzeros (0.41 against 0.16 ms, two threads). Its stored zeros move
   * with the contact from one Newton iteration to the next, so a
   * SparsityPattern of the nonzeros would have to be built for nearly every
   * solve, and building one sorts every row; these rows are written in two
   * passes over the matrix on the threads, about the cost of two products with
   * it.
   *
   * A row keeps the order of the matrix's (the diagonal first, then the
   * other columns in ascending order) and its product sums in that order
   * from zero, as SparseMatrix::vmult() does: the products are bit for bit
   * those with the matrix (a stored zero adds nothing).
   */
  class NonzeroMatrix
  {
  public:
    /** Take the nonzeros of the square @p A, and its diagonal. */
    void
    copy_from(const SparseMatrix<double> &A);

    /** @p y = A @p x, on the threads. */
    void
    vmult(Vector<double> &y, const Vector<double> &x) const;

    /** Rows (= columns). */
    types::global_dof_index
    m() const
    {
      return row_start.empty() ? 0 : row_start.size() - 1;
    }

    /** Entries kept. */
    std::size_t
    n_nonzero_elements() const
    {
      return m() == 0 ? 0 : row_start.back();
    }

  private:
    /** Row i's entries are [row_start[i], row_start[i + 1]). */
    std::vector<std::size_t>             row_start;
    std::vector<types::global_dof_index> column;
    std::vector<double>                  value;
  };
} // namespace TissueContact
