#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <vector>

namespace TissueContact
{
  namespace Scene
  {
    using namespace dealii;

    /**
     * A rigid motion scaled by the load factor @f$\lambda@f$: a rotation by
     * @f$\lambda\theta@f$ about the axis @f$a@f$ through the center @f$c@f$,
     * then a translation @f$\lambda d@f$. The displacement of the reference
     * point @f$X@f$ is
     * @f[ u(X,\lambda) = R(\lambda\theta, a)(X - c) + c - X + \lambda d. @f]
     * With @f$\theta = 0@f$ and @f$d = 0@f$ it clamps (u = 0).
     */
    struct PrescribedMotion
    {
      Tensor<1, 3> translation;
      Tensor<1, 3> axis{{0., 0., 1.}};
      Point<3>     center;
      double       angle = 0.; // radians
      /** Waypoints of the translation; empty: @f$\lambda d@f$. */
      std::vector<Tensor<1, 3>> path;

      /** The translation at the load factor @p load_factor. */
      Tensor<1, 3>
      translation_at(const double load_factor) const;

      Tensor<1, 3>
      displacement(const Point<3> &X, const double load_factor) const;
    };
  } // namespace Scene
} // namespace TissueContact
