#pragma once

#include <tissue_contact/materials/hyperelastic_material.h>

namespace TissueContact
{
  namespace Materials
  {
    /**
     * The invariants of @f$C@f$ used by every isotropic model:
     * @f$I_1 = \mathrm{tr}\,C@f$,
     * @f$I_2 = \frac12[(\mathrm{tr}\,C)^2 - \mathrm{tr}(C^2)]@f$,
     * @f$I_3 = \det C = J^2@f$.
     */
    struct Invariants
    {
      double I1, I2, I3;
    };

    /**
     * Derivatives of @f$\Psi(I_1,I_2,I_3)@f$: @p d[i] @f$=\Psi_i =
     * \partial\Psi/\partial I_{i+1}@f$ and @p dd[i][j] @f$=\Psi_{ij}@f$.
     */
    struct InvariantDerivatives
    {
      double d[3]     = {0., 0., 0.};
      double dd[3][3] = {{0., 0., 0.}, {0., 0., 0.}, {0., 0., 0.}};
    };

    /**
     * An isotropic hyperelastic material @f$\Psi(I_1, I_2, I_3)@f$. With
     * @f$G_1 = I@f$, @f$G_2 = I_1 I - C@f$, @f$G_3 = I_3 C^{-1}@f$
     * (@f$G_i = \partial I_i/\partial C@f$) it computes
     * @f[ S = 2\sum_i \Psi_i G_i, @f]
     * @f[ \mathbb{C} = 4\Big[\sum_{ij}\Psi_{ij}\,G_i\otimes G_j
     *      + \Psi_2\,(I\otimes I - \mathbb{I})
     *      + \Psi_3\,I_3\,(C^{-1}\otimes C^{-1} - C^{-1}\odot C^{-1})\Big] @f]
     * (doc/theory/03-materials.md, eqs. (M2)-(M4)), and the same pushed
     * forward to the current configuration ((M3S)). A model only provides
     * @f$\Psi@f$ and its first and second invariant derivatives.
     */
    class IsotropicMaterial : public HyperelasticMaterial
    {
    public:
      /** @f$\Psi@f$ as a function of the invariants. */
      virtual double
      psi(const Invariants &I) const = 0;

      /** @f$\Psi_i@f$ and @f$\Psi_{ij}@f$. */
      virtual InvariantDerivatives
      psi_derivatives(const Invariants &I) const = 0;

      /** The invariants of @p C. */
      static Invariants
      invariants(const SymmetricTensor<2, 3> &C);

      double
      energy_C(const SymmetricTensor<2, 3> &C,
               const Point<3>              &X) const override;

      void
      stress_C(const SymmetricTensor<2, 3> &C,
               const Point<3>              &X,
               SymmetricTensor<2, 3>       &S,
               VoigtTangent                *CC) const override;
      /** (M3S): the closed form of stress_C() pushed forward. */
      void
      stress_b(const Tensor<2, 3>    &F,
               const Point<3>        &X,
               SymmetricTensor<2, 3> &tau,
               VoigtTangent          *c) const override;
    };
  } // namespace Materials
} // namespace TissueContact
