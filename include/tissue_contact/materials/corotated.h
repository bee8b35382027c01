#pragma once

#include <tissue_contact/materials/hyperelastic_material.h>

namespace TissueContact
{
  namespace Materials
  {
    /**
     * Corotated linear elasticity: linear elasticity in the stretch
     * @f$U = C^{1/2}@f$ of the polar decomposition @f$F = RU@f$,
     * @f$\Psi = \mu|U-I|^2 + \frac{\lambda}{2}(\mathrm{tr}\,U - 3)^2@f$,
     * @f$S = U^{-1}T@f$ with the corotated stress
     * @f$T = 2\mu(U-I) + \lambda(\mathrm{tr}\,U-3)I@f$ (so @f$P = RT@f$),
     * and the exact tangent (M7) of doc/theory/03-materials.md sec. 3.6,
     * all from one symmetric eigendecomposition of @f$C@f$. Objective, with
     * linear elasticity's small-strain response; no energy barrier at
     * @f$J\to 0@f$.
     */
    class Corotated : public HyperelasticMaterial
    {
    public:
      Corotated(const double mu, const double lambda);

      std::string
      name() const override
      {
        return "corotated";
      }
      double
      energy_C(const SymmetricTensor<2, 3> &C,
               const Point<3>              &X) const override;
      void
      stress_C(const SymmetricTensor<2, 3> &C,
               const Point<3>              &X,
               SymmetricTensor<2, 3>       &S,
               VoigtTangent                *CC) const override;
      std::pair<double, double>
      lame_equivalents() const override
      {
        return {mu, lambda};
      }

    private:
      const double mu, lambda;
    };
  } // namespace Materials
} // namespace TissueContact
