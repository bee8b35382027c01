#include <tissue_contact/materials/hyperelastic_material.h>

namespace TissueContact
{
  namespace Materials
  {
    namespace
    {
      SymmetricTensor<2, 3>
      right_cauchy_green(const Tensor<2, 3> &F)
      {
        return symmetrize(transpose(F) * F);
      }
    } // namespace


    double
    HyperelasticMaterial::energy(const Tensor<2, 3> &F, const Point<3> &X) const
    {
      return energy_C(right_cauchy_green(F), X);
    }


    Tensor<2, 3>
    HyperelasticMaterial::first_piola_kirchhoff(const Tensor<2, 3> &F,
                                                const Point<3>     &X) const
    {
      SymmetricTensor<2, 3> S;
      stress_C(right_cauchy_green(F), X, S, nullptr);
      return F * static_cast<Tensor<2, 3>>(S);
    }


    void
    HyperelasticMaterial::evaluate(const Tensor<2, 3> &F,
                                   const Point<3>     &X,
                                   MaterialResponse   &response) const
    {
      const SymmetricTensor<2, 3> C = right_cauchy_green(F);
      SymmetricTensor<2, 3>       S;
      VoigtTangent                CC;
      stress_C(C, X, S, &CC);
      response.psi = energy_C(C, X);
      push_forward_tangent(
        F, static_cast<Tensor<2, 3>>(S), CC.tensor(), response.P, response.A);
    }
  } // namespace Materials
} // namespace TissueContact
