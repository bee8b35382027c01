#pragma once

#include <tissue_contact/materials/material.h>

namespace TissueContact
{
  namespace Materials
  {
    /**
     * Linear (small-strain) elasticity, the cheapest model:
     * @f$\varepsilon = \mathrm{sym}(F) - I@f$,
     * @f$\Psi = \frac{\lambda}{2}(\mathrm{tr}\,\varepsilon)^2
     *          + \mu\,\varepsilon:\varepsilon@f$, @f$P = \sigma(\varepsilon)
     *  = \lambda\,\mathrm{tr}\,\varepsilon\,I + 2\mu\varepsilon@f$ and a
     * constant tangent. It is not objective: wrong for large rotations
     * (tests/solvers/newton_static shows by how much).
     */
    class LinearElastic : public Material
    {
    public:
      LinearElastic(const double mu, const double lambda);

      std::string
      name() const override
      {
        return "linear";
      }
      double
      energy(const Tensor<2, 3> &F, const Point<3> &X) const override;
      Tensor<2, 3>
      first_piola_kirchhoff(const Tensor<2, 3> &F,
                            const Point<3>     &X) const override;
      void
      evaluate(const Tensor<2, 3> &F,
               const Point<3>     &X,
               MaterialResponse   &response) const override;
      std::pair<double, double>
      lame_equivalents() const override
      {
        return {mu, lambda};
      }

    private:
      const double mu, lambda;
      Tensor<4, 3> A_constant;
    };
  } // namespace Materials
} // namespace TissueContact
