#include <tissue_contact/materials/linear_elastic.h>

namespace TissueContact
{
  namespace Materials
  {
    LinearElastic::LinearElastic(const double mu, const double lambda)
      : mu(mu)
      , lambda(lambda)
    {
      check_stable_lame_parameters(name(), mu, lambda);
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int J = 0; J < 3; ++J)
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int L = 0; L < 3; ++L)
              A_constant[i][J][k][L] =
                lambda * (i == J) * (k == L) +
                mu * ((i == k) * (J == L) + (i == L) * (J == k));
    }


    double
    LinearElastic::energy(const Tensor<2, 3> &F, const Point<3> &) const
    {
      const SymmetricTensor<2, 3> eps =
        symmetrize(F) - unit_symmetric_tensor<3>();
      const double tr = trace(eps);
      return 0.5 * lambda * tr * tr + mu * (eps * eps);
    }


    Tensor<2, 3>
    LinearElastic::first_piola_kirchhoff(const Tensor<2, 3> &F,
                                         const Point<3> &) const
    {
      const SymmetricTensor<2, 3> eps =
        symmetrize(F) - unit_symmetric_tensor<3>();
      return static_cast<Tensor<2, 3>>(
        lambda * trace(eps) * unit_symmetric_tensor<3>() + 2. * mu * eps);
    }


    void
    LinearElastic::evaluate(const Tensor<2, 3> &F,
                            const Point<3>     &X,
                            MaterialResponse   &response) const
    {
      response.psi = energy(F, X);
      response.P   = first_piola_kirchhoff(F, X);
      response.A   = A_constant;
    }
  } // namespace Materials
} // namespace TissueContact
