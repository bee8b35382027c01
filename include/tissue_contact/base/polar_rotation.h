#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

namespace TissueContact
{
  using namespace dealii;

  /**
   * The rotation @f$R@f$ of the polar decomposition @f$F = RU@f$
   * (@f$\det F > 0@f$) and its first and second derivatives with respect to
   * @f$F@f$ (doc/theory/10-single-rotation.md sec. 10.2):
   * @f$\mathrm dR = R\hat\omega@f$ with
   * @f$\omega = M^{-1}\mathrm{axial}(R^T\mathrm dF - \mathrm dF^TR)@f$,
   * @f$M = (\mathrm{tr}\,U)I - U@f$ (SR2), and
   * @f$\mathrm d^2R[\mathrm dF_1,\mathrm dF_2]@f$ (SR3). @f$U@f$ comes from
   * one symmetric eigendecomposition of @f$C = F^TF@f$.
   */
  class PolarRotation
  {
  public:
    /** Decompose @p F; its determinant must be positive. */
    explicit PolarRotation(const Tensor<2, 3> &F);

    const Tensor<2, 3> &
    R() const
    {
      return rotation;
    }

    const SymmetricTensor<2, 3> &
    U() const
    {
      return stretch;
    }

    /** The axial vector @f$\omega@f$ of @f$R^T\mathrm dR@f$ (SR2). */
    Tensor<1, 3>
    omega(const Tensor<2, 3> &dF) const;

    /** @f$\mathrm dR = R\hat\omega@f$ (SR2). */
    Tensor<2, 3>
    dR(const Tensor<2, 3> &dF) const;

    /**
     * @f$R^T\mathrm d^2R[\mathrm dF_1,\mathrm dF_2] =
     * \hat\omega_2\hat\omega_1 + \widehat{\mathrm d\omega_1}@f$ (SR3),
     * given @f$\omega_1@f$ and @f$\omega_2@f$ of the two directions
     * (omega()); symmetric in the two directions.
     */
    Tensor<2, 3>
    Rt_d2R(const Tensor<2, 3> &dF1,
           const Tensor<1, 3> &omega1,
           const Tensor<2, 3> &dF2,
           const Tensor<1, 3> &omega2) const;

    /** @f$\mathrm d^2R[\mathrm dF_1,\mathrm dF_2]@f$ (SR3). */
    Tensor<2, 3>
    d2R(const Tensor<2, 3> &dF1, const Tensor<2, 3> &dF2) const;

    /** The axial vector of a skew matrix @p W: @f$\hat w = W@f$
     * (@f$\hat w@f$ = cross_matrix(w), base/cross_matrix.h). */
    static Tensor<1, 3>
    axial(const Tensor<2, 3> &W);

  private:
    Tensor<2, 3>          rotation;
    SymmetricTensor<2, 3> stretch;
    Tensor<2, 3>          M_inverse;
  };
} // namespace TissueContact
