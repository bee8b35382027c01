#pragma once

#include <tissue_contact/materials/hyperelastic_material.h>

#include <deal.II/base/function.h>

#include <memory>

namespace TissueContact
{
  namespace Materials
  {
    /**
     * Fiber reinforcement added to a hyperelastic ground material
     * (Hirota et al. 2001, sec. 3.3; dissertation 3.6.7, made stress free):
     * @f[ \Psi = \Psi_{\rm ground}(C)
     *        + \alpha_f\big(e^{\beta_f(\lambda_f^2-1)} - 1\big)
     *        - \alpha_f\beta_f(\lambda_f^2 - 1),
     *   \qquad \lambda_f^2 = f\cdot C f, @f]
     * with the unit fiber direction @f$f(X)@f$ in the reference
     * configuration. It adds @f$S_f = 2\Psi_f' f\otimes f@f$ and
     * @f$\mathbb{C}_f = 4\Psi_f'' f\otimes f\otimes f\otimes f@f$ with
     * @f$\Psi_f' = \alpha_f\beta_f(e^{\beta_f(\lambda_f^2-1)} - 1)@f$ and
     * @f$\Psi_f'' = \alpha_f\beta_f^2 e^{\beta_f(\lambda_f^2-1)}@f$
     * (doc/theory/03-materials.md, sec. 5). The fibers resist stretch and
     * compression alike (no tension-only switch), as in the sources.
     */
    class FiberReinforcement : public HyperelasticMaterial
    {
    public:
      /**
       * @p direction is a function with 3 components evaluated at the
       * reference point; it is normalized there and must not vanish.
       */
      FiberReinforcement(std::unique_ptr<HyperelasticMaterial> ground,
                         const double                          alpha_f,
                         const double                          beta_f,
                         std::shared_ptr<const Function<3>>    direction);

      std::string
      name() const override;

      /** The unit fiber direction at @p X. */
      Tensor<1, 3>
      fiber_direction(const Point<3> &X) const;

      double
      energy_C(const SymmetricTensor<2, 3> &C,
               const Point<3>              &X) const override;
      void
      stress_C(const SymmetricTensor<2, 3> &C,
               const Point<3>              &X,
               SymmetricTensor<2, 3>       &S,
               VoigtTangent                *CC) const override;
      /** stress_C() pushed forward, in closed form. */
      void
      stress_b(const Tensor<2, 3>    &F,
               const Point<3>        &X,
               SymmetricTensor<2, 3> &tau,
               VoigtTangent          *c) const override;
      /** The ground material's equivalents (the fibers add anisotropic
       * stiffness @f$4\alpha_f\beta_f^2@f$ along @f$f\otimes f\otimes f
       * \otimes f@f$ only). */
      std::pair<double, double>
      lame_equivalents() const override
      {
        return ground->lame_equivalents();
      }

    private:
      /** The fiber term with @p v = f (material) or a = F f (spatial) and
       * the fiber stretch squared @p lf2: @p stress += 2 Psi_f' v (x) v,
       * @p tangent += 4 Psi_f'' v (x) v (x) v (x) v. */
      void
      add_fiber(const Tensor<1, 3>    &v,
                const double           lf2,
                SymmetricTensor<2, 3> &stress,
                VoigtTangent          *tangent) const;

      std::unique_ptr<HyperelasticMaterial> ground;
      const double                          alpha_f, beta_f;
      std::shared_ptr<const Function<3>>    direction;
    };
  } // namespace Materials
} // namespace TissueContact
