#pragma once

#include <tissue_contact/materials/isotropic_material.h>

namespace TissueContact
{
  namespace Materials
  {
    /**
     * Compressible neo-Hookean material, the cheap model:
     * @f$\Psi = \frac{\mu}{2}(I_1 - 3) - \mu\ln J + \frac{\lambda}{2}(\ln
     * J)^2@f$ with @f$\ln J = \frac12\ln I_3@f$ (doc/theory/03-materials.md).
     */
    class NeoHookean : public IsotropicMaterial
    {
    public:
      /** Throws if @f$\mu \le 0@f$ or the bulk modulus is not positive. */
      NeoHookean(const double mu, const double lambda);

      std::string
      name() const override
      {
        return "neo-Hookean";
      }
      double
      psi(const Invariants &I) const override;
      InvariantDerivatives
      psi_derivatives(const Invariants &I) const override;
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
