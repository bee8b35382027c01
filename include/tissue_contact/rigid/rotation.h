#pragma once

#include <deal.II/base/tensor.h>

#include <array>

namespace TissueContact
{
  namespace Rigid
  {
    using namespace dealii;

    /**
     * The rotation @f$R(\theta) = \exp([\theta]_\times) = I + a(s)
     * [\theta]_\times + b(s) [\theta]_\times^2@f$ of a rotation vector
     * @f$\theta@f$, @f$s = \theta\cdot\theta@f$, with its first and second
     * derivatives @f$\partial R/\partial\theta_k@f$ and
     * @f$\partial^2 R/\partial\theta_k\partial\theta_l@f$ (doc/theory/07
     * sec. 2). The coefficients @f$a = \sin|\theta|/|\theta|@f$ and
     * @f$b = (1-\cos|\theta|)/|\theta|^2@f$ are evaluated as their power
     * series in s, smooth at @f$\theta = 0@f$, and the derivatives by
     * forward-over-forward automatic differentiation (Sacado), exact to
     * rounding for @f$|\theta| < 2\pi@f$.
     */
    struct RotationDerivatives
    {
      Tensor<2, 3>                               R;
      std::array<Tensor<2, 3>, 3>                dR;
      std::array<std::array<Tensor<2, 3>, 3>, 3> d2R;
    };

    /** R, dR, d2R at @p theta. */
    RotationDerivatives
    rotation(const Tensor<1, 3> &theta);
  } // namespace Rigid
} // namespace TissueContact
