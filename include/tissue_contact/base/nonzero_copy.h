#pragma once

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

namespace TissueContact
{
  using namespace dealii;

  /**
   * Copy the square matrix @p A into @p copy on @p pattern without the
   * entries that are stored but exactly zero (the diagonal is kept in every
   * row). A product with the copy is bit for bit that with @p A (a stored
   * zero adds nothing) and visits only the nonzeros: on tangents of the
   * full knee, whose patterns hold the zeroed rows and columns of
   * prescribed DoFs and the couplings of contact candidates not in
   * contact, 37-43 % of the stored entries (doc/theory/04-solver.md sec.
   * 4.5.2). @p copy is cleared first, so @p pattern may be its old one.
   * Cost, on a tangent of the full knee (29 706 rows, 2.24 million stored
   * entries, one thread): 25 ms, against 1.07 ms for a product with @p A
   * and 0.32 ms with the copy. It is the matrix ML's hierarchy is built
   * from (Trilinos' copy is made of it), once per hierarchy, and the one
   * the direct fallback of Type = automatic factorizes; the products
   * of GMRES and of the cycle's finest level use a NonzeroMatrix, which
   * needs no SparsityPattern and is taken in 5.5-8 ms (one thread;
   * base/nonzero_matrix.h).
   */
  void
  copy_nonzeros(const SparseMatrix<double> &A,
                SparsityPattern            &pattern,
                SparseMatrix<double>       &copy);
} // namespace TissueContact
