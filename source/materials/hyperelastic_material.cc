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
    HyperelasticMaterial::stress_b(const Tensor<2, 3>    &F,
                                   const Point<3>        &X,
                                   SymmetricTensor<2, 3> &tau,
                                   VoigtTangent          *c) const
    {
      SymmetricTensor<2, 3> S;
      VoigtTangent          CC;
      stress_C(right_cauchy_green(F), X, S, c != nullptr ? &CC : nullptr);
      // tau = F S F^T, its 6 entries
      const Tensor<2, 3> FS    = F * static_cast<Tensor<2, 3>>(S);
      const auto        &index = VoigtTangent::index;
      for (unsigned int p = 0; p < 6; ++p)
        {
          const unsigned int i = index[p][0], j = index[p][1];
          tau[i][j] = FS[i] * F[j];
        }
      if (c == nullptr)
        return;
      // c = T D T^T: T_pr = F_{i_p I_r} F_{j_p J_r}, plus the transposed
      // pair for a shear r (doc/theory/02, after (L6))
      double T[6][6];
      for (unsigned int p = 0; p < 6; ++p)
        for (unsigned int r = 0; r < 6; ++r)
          {
            const unsigned int i = index[p][0], j = index[p][1];
            const unsigned int I = index[r][0], J = index[r][1];
            T[p][r] = F[i][I] * F[j][J] + (I != J ? F[i][J] * F[j][I] : 0.);
          }
      double TD[6][6];
      for (unsigned int p = 0; p < 6; ++p)
        for (unsigned int s = 0; s < 6; ++s)
          {
            double v = 0.;
            for (unsigned int r = 0; r < 6; ++r)
              v += T[p][r] * CC.D[r][s];
            TD[p][s] = v;
          }
      for (unsigned int p = 0; p < 6; ++p)
        for (unsigned int q = p; q < 6; ++q)
          {
            double v = 0.;
            for (unsigned int s = 0; s < 6; ++s)
              v += TD[p][s] * T[q][s];
            c->D[p][q] = c->D[q][p] = v;
          }
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
