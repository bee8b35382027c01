#pragma once

#include <tissue_contact/materials/isotropic_material.h>

namespace TissueContact
{
  namespace Materials
  {
    /**
     * Compressible Veronda-Westmann material in the corrected form of
     * doc/theory/03-materials.md, sec. 4:
     * @f$\Psi = \alpha(e^{\beta(I_1-3)} - 1) - \frac{\alpha\beta}{2}(I_2-3)
     *          + a(I_3-1) - a\ln I_3@f$.
     * Stress free at @f$C = I@f$ with @f$\mu = \alpha\beta@f$,
     * @f$\lambda = 4(\alpha\beta^2 - \alpha\beta/2 + a)@f$. The forms printed
     * in the paper and in the dissertation are wrong; the document explains
     * why and tests/materials/material_derivatives checks it.
     */
    class Veronda : public IsotropicMaterial
    {
    public:
      /** Throws unless @f$\alpha>0@f$, @f$\beta>0@f$, @f$a>0@f$ and the
       * small-strain bulk modulus is positive. */
      Veronda(const double alpha, const double beta, const double a);

      std::string
      name() const override
      {
        return "Veronda";
      }
      double
      psi(const Invariants &I) const override;
      InvariantDerivatives
      psi_derivatives(const Invariants &I) const override;
      std::pair<double, double>
      lame_equivalents() const override
      {
        return {alpha * beta,
                4. * (alpha * beta * beta - alpha * beta / 2. + a)};
      }

    private:
      const double alpha, beta, a;
    };
  } // namespace Materials
} // namespace TissueContact
