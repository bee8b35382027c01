#pragma once

#include <tissue_contact/materials/material.h>
#include <tissue_contact/materials/voigt_tangent.h>

namespace TissueContact
{
  namespace Materials
  {
    /**
     * A hyperelastic material written in terms of the right Cauchy-Green
     * tensor @f$C = F^TF@f$: it provides @f$\Psi(C)@f$, the second
     * Piola-Kirchhoff stress @f$S = 2\,\partial\Psi/\partial C@f$ and the
     * material elasticity tensor
     * @f$\mathbb{C} = 4\,\partial^2\Psi/\partial C\partial C@f$; this class
     * turns them into @f$P@f$ and @f$\mathcal{A}@f$ with
     * push_forward_tangent(). Such materials are objective by construction.
     */
    class HyperelasticMaterial : public Material
    {
    public:
      /** @f$\Psi(C)@f$. */
      virtual double
      energy_C(const SymmetricTensor<2, 3> &C, const Point<3> &X) const = 0;

      /** @f$S(C)@f$, and @f$\mathbb{C}(C)@f$ in Voigt form when @p CC is
       * not null (every entry of CC->D is set). */
      virtual void
      stress_C(const SymmetricTensor<2, 3> &C,
               const Point<3>              &X,
               SymmetricTensor<2, 3>       &S,
               VoigtTangent                *CC) const = 0;

      /**
       * The Kirchhoff stress @f$\tau = FSF^T@f$ and, when @p c is not
       * null, the spatial tangent @f$c^\tau_{ijkl} = F_{iI}F_{jJ}F_{kK}
       * F_{lL}\,\mathbb{C}_{IJKL}@f$ in Voigt form (the order and
       * convention of VoigtTangent) at @p F, for the spatial form of the
       * tangent (doc/theory/02-weak-form-and-linearization.md, (L5)). By
       * default pushed forward from stress_C(): @f$c^\tau = TDT^T@f$;
       * IsotropicMaterial overrides it in closed form.
       */
      virtual void
      stress_b(const Tensor<2, 3>    &F,
               const Point<3>        &X,
               SymmetricTensor<2, 3> &tau,
               VoigtTangent          *c) const;
      double
      energy(const Tensor<2, 3> &F, const Point<3> &X) const override;

      Tensor<2, 3>
      first_piola_kirchhoff(const Tensor<2, 3> &F,
                            const Point<3>     &X) const override;

      void
      evaluate(const Tensor<2, 3> &F,
               const Point<3>     &X,
               MaterialResponse   &response) const override;
    };
  } // namespace Materials
} // namespace TissueContact
