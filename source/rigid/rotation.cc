#include <tissue_contact/rigid/rotation.h>

#include <deal.II/differentiation/ad/sacado_number_types.h>

namespace TissueContact
{
  namespace Rigid
  {
    RotationDerivatives
    rotation(const Tensor<1, 3> &theta)
    {
      using Inner = Sacado::Fad::DFad<double>;
      using AD    = Sacado::Fad::DFad<Inner>;

      std::array<AD, 3> t;
      for (unsigned int i = 0; i < 3; ++i)
        t[i] = AD(3, i, Inner(3, i, theta[i]));
      const AD s = t[0] * t[0] + t[1] * t[1] + t[2] * t[2];

      // a(s) = sum_k (-s)^k / (2k+1)!, b(s) = sum_k (-s)^k / (2k+2)!, by
      // Horner; 30 terms leave a remainder below 1e-30 for s <= (2 pi)^2
      constexpr unsigned int              n_terms = 30;
      std::array<double, 2 * n_terms + 3> inverse_factorial;
      inverse_factorial[0] = 1.;
      for (unsigned int k = 1; k < inverse_factorial.size(); ++k)
        inverse_factorial[k] = inverse_factorial[k - 1] / k;
      AD a = 0., b = 0.;
      for (int k = n_terms; k >= 0; --k)
        {
          a = a * (-s) + inverse_factorial[2 * k + 1];
          b = b * (-s) + inverse_factorial[2 * k + 2];
        }

      // W = [theta]_x, R = I + a W + b W^2
      std::array<std::array<AD, 3>, 3> W;
      W[0][0] = 0.;
      W[0][1] = -t[2];
      W[0][2] = t[1];
      W[1][0] = t[2];
      W[1][1] = 0.;
      W[1][2] = -t[0];
      W[2][0] = -t[1];
      W[2][1] = t[0];
      W[2][2] = 0.;

      RotationDerivatives r;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          {
            AD W2 = 0.;
            for (unsigned int k = 0; k < 3; ++k)
              W2 += W[i][k] * W[k][j];
            const AD Rij = (i == j ? 1. : 0.) + a * W[i][j] + b * W2;
            r.R[i][j]    = Rij.val().val();
            for (unsigned int k = 0; k < 3; ++k)
              {
                r.dR[k][i][j] = Rij.dx(k).val();
                for (unsigned int l = 0; l < 3; ++l)
                  r.d2R[k][l][i][j] = Rij.dx(k).dx(l);
              }
          }
      return r;
    }
  } // namespace Rigid
} // namespace TissueContact
