#pragma once

#include <deal.II/base/tensor.h>

namespace TissueContact
{
  using namespace dealii;

  /** @f$[a]_\times@f$, the skew matrix of @f$v \mapsto a \times v@f$. */
  inline Tensor<2, 3>
  cross_matrix(const Tensor<1, 3> &a)
  {
    return Tensor<2, 3>(
      {{0., -a[2], a[1]}, {a[2], 0., -a[0]}, {-a[1], a[0], 0.}});
  }
} // namespace TissueContact
