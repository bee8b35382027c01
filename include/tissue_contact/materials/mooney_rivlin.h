#pragma once

#include <tissue_contact/materials/isotropic_material.h>

namespace TissueContact
{
  namespace Materials
  {
    /**
     * Compressible Mooney-Rivlin material (Hirota et al. 2001, sec. 3.3,
     * with the standard second invariant):
     * @f$\Psi = C_1(I_1-3) + C_2(I_2-3) + a(I_3-1) - (C_1+2C_2+a)\ln I_3@f$.
     * Small-strain equivalents @f$\mu = 2(C_1+C_2)@f$,
     * @f$\lambda = 4(C_2+a)@f$ (doc/theory/03-materials.md, sec. 3).
     */
    class MooneyRivlin : public IsotropicMaterial
    {
    public:
      /** Throws unless @f$\mu > 0@f$, bulk modulus > 0, and
       * @f$C_1+2C_2+a > 0@f$ (energy barrier at @f$J\to 0@f$). */
      MooneyRivlin(const double C1, const double C2, const double a);

      std::string
      name() const override
      {
        return "Mooney-Rivlin";
      }
      double
      psi(const Invariants &I) const override;
      InvariantDerivatives
      psi_derivatives(const Invariants &I) const override;
      std::pair<double, double>
      lame_equivalents() const override
      {
        return {2. * (C1 + C2), 4. * (C2 + a)};
      }

    private:
      const double C1, C2, a;
    };
  } // namespace Materials
} // namespace TissueContact
