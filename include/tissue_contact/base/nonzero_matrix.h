#pragma once

#include <tissue_contact/base/compressed_rows.h>

#include <deal.II/base/subscriptor.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <cstddef>
#include <vector>

namespace TissueContact
{
  using namespace dealii;

  /**
   * The nonzero entries of a square SparseMatrix, taken anew from each
   * matrix, in groups of three rows, and their products: the operator GMRES
   * multiplies with and the finest level of the AMG cycle (doc/theory/
   * 04-solver.md sec. 4.5.2).
   *
   * The tangent of a contact scene stores many zeros: the zeroed rows and
   * columns of prescribed DoFs and the couplings of contact candidates not
   * in contact. On a tangent of the full knee that is 61 % of 2.08 million
   * stored entries, and a product with the tangent costs 2.5 products with
   * its nonzeros (0.41 against 0.16 ms, two threads). Its stored zeros move
   * with the contact from one Newton iteration to the next, so a
   * SparsityPattern of the nonzeros would have to be built for nearly every
   * solve, and building one sorts every row; these groups are written in
   * two passes over the matrix on the threads.
   *
   * Rows 3g, 3g + 1, 3g + 2 (a vertex's three displacement components, in
   * deal.II's numbering of a vector-valued P1 or P2 element) form group g:
   * their diagonals, and the union of their other nonzero columns in
   * ascending order, each column with the three rows' values (zero where a
   * row has none there, and for a row's own diagonal). A product sums each
   * row as SparseMatrix::vmult() does, from zero, the diagonal first, then
   * the other columns in ascending order, so the products are those with
   * the matrix to the last bit (an entry that is zero adds nothing; only
   * the sign of a sum that is exactly zero can differ). The three rows'
   * sums are independent chains of additions, run side by side: a row's
   * sum is one chain of dependent additions, whose latency, not the memory,
   * bounds SparseMatrix::vmult() (on a P1 tetrahedral mesh of 10 125 DoFs,
   * one thread, 0.18 against 0.09 ms per product).
   */
  class NonzeroMatrix : public Subscriptor
  {
  public:
    /** Take the nonzeros of the square @p A, and its diagonal. */
    void
    copy_from(const SparseMatrix<double> &A);

    /** Take the square @p A (its rows sorted, without zeros), and its
     * diagonal: the same as from a SparseMatrix of these entries, without
     * building one (an AMG level's Galerkin product). */
    void
    copy_from(const CompressedRows &A);

    /** @p y = A @p x, on the threads. */
    void
    vmult(Vector<double> &y, const Vector<double> &x) const;

    /** @p r = @p b - A @p x, on the threads, each row summed as
     * SparseMatrix::residual() does (from b, the diagonal's term first). */
    void
    residual(Vector<double>       &r,
             const Vector<double> &x,
             const Vector<double> &b) const;

    /** Rows (= columns). */
    types::global_dof_index
    m() const
    {
      return diagonal.size();
    }

    /** Columns (= rows). */
    types::global_dof_index
    n() const
    {
      return diagonal.size();
    }

    /** The entries kept: the diagonal and the other nonzeros. */
    std::size_t
    n_nonzero_elements() const
    {
      return n_nonzeros;
    }

    /** Entry (i, j); zero if it is not kept. */
    double
    el(const types::global_dof_index i, const types::global_dof_index j) const;

    /** Diagonal entry i. */
    double
    diag_element(const types::global_dof_index i) const
    {
      return diagonal[i];
    }

    /** Groups of three rows (the last may hold fewer). */
    types::global_dof_index
    n_groups() const
    {
      return group_start.size() - 1;
    }

    /** Group @p g's other columns than the diagonals, ascending: indices
     * group_begin(g) ... group_end(g) - 1 of column() and values(). */
    std::size_t
    group_begin(const types::global_dof_index g) const
    {
      return group_start[g];
    }

    /** One past group @p g's last column. */
    std::size_t
    group_end(const types::global_dof_index g) const
    {
      return group_start[g + 1];
    }

    /** Column of the groups' entry @p k. */
    types::global_dof_index
    column_of(const std::size_t k) const
    {
      return column[k];
    }

    /** The three rows' values of the groups' entry @p k (zero where a row
     * has none, and at a row's own diagonal). */
    const double *
    values_of(const std::size_t k) const
    {
      return value.data() + 3 * k;
    }

  private:
    /** Pass 1 of a copy of a matrix of @p n rows: group g's count of
     * columns and of nonzeros off the diagonal, @p count(g) (a pair), on
     * the threads; group_start and n_nonzeros from them, the arrays sized
     * for pass 2. */
    template <typename Count>
    void
    size_groups(const types::global_dof_index n, const Count &count);

    /** @p y = A @p x, or @p y = *@p b - A @p x if @p residual. */
    template <bool residual>
    void
    products(Vector<double>       &y,
             const Vector<double> &x,
             const Vector<double> *b) const;

    /** Group g's columns are column[group_start[g]] ...
     * column[group_start[g + 1] - 1], their values value[3 k + c] for row
     * 3 g + c. */
    std::vector<std::size_t>             group_start;
    std::vector<types::global_dof_index> column;
    std::vector<double>                  value;
    std::vector<double>                  diagonal;
    std::size_t                          n_nonzeros = 0;
  };
} // namespace TissueContact
