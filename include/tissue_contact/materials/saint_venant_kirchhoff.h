#pragma once

#include <tissue_contact/materials/isotropic_material.h>

namespace TissueContact
{
  namespace Materials
  {
    /**
     * Saint Venant-Kirchhoff material
     * @f$\Psi = \frac{\lambda}{2}(\mathrm{tr}E)^2 + \mu\,\mathrm{tr}(E^2)@f$,
     * written in invariants as
     * @f$\Psi = \frac{\lambda}{8}(I_1-3)^2
     *         + \frac{\mu}{4}(I_1^2 - 2I_2 - 2I_1 + 3)@f$.
     * Exact for large rotations, but it has no energy barrier at
     * @f$J \to 0@f$ and softens in strong compression.
     */
    class SaintVenantKirchhoff : public IsotropicMaterial
    {
    public:
      SaintVenantKirchhoff(const double mu, const double lambda);

      std::string
      name() const override
      {
        return "Saint Venant-Kirchhoff";
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
