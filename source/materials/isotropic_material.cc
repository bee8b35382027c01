#include <tissue_contact/materials/isotropic_material.h>

namespace TissueContact
{
  namespace Materials
  {
    Invariants
    IsotropicMaterial::invariants(const SymmetricTensor<2, 3> &C)
    {
      const double I1 = trace(C);
      return {I1, 0.5 * (I1 * I1 - C * C), determinant(C)};
    }


    double
    IsotropicMaterial::energy_C(const SymmetricTensor<2, 3> &C,
                                const Point<3> &) const
    {
      return psi(invariants(C));
    }


    void
    IsotropicMaterial::stress_C(const SymmetricTensor<2, 3> &C,
                                const Point<3> &,
                                SymmetricTensor<2, 3> &S,
                                SymmetricTensor<4, 3> *CC) const
    {
      const Invariants            I     = invariants(C);
      const InvariantDerivatives  D     = psi_derivatives(I);
      const SymmetricTensor<2, 3> Id    = unit_symmetric_tensor<3>();
      const SymmetricTensor<2, 3> C_inv = invert(C);

      // G_i = dI_i/dC
      const SymmetricTensor<2, 3> G[3] = {Id, I.I1 * Id - C, I.I3 * C_inv};

      S = 2. * (D.d[0] * G[0] + D.d[1] * G[1] + D.d[2] * G[2]);

      if (CC == nullptr)
        return;

      // one pass over the 36 independent entries (A <= B, K <= L):
      // sum_ij Psi_ij G_i x G_j
      //   + Psi_2 (I x I - II)                          [d^2 I2 / dC dC]
      //   + Psi_3 I3 (C^-1 x C^-1 - C^-1 (.) C^-1)      [d^2 I3 / dC dC]
      SymmetricTensor<4, 3> &T  = *CC;
      const double           c3 = D.d[2] * I.I3;
      for (unsigned int A = 0; A < 3; ++A)
        for (unsigned int B = A; B < 3; ++B)
          {
            const double gAB[3] = {G[0][A][B], G[1][A][B], G[2][A][B]};
            double       hAB[3] = {0., 0., 0.}; // sum_i Psi_ij G_i,AB
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int j = 0; j < 3; ++j)
                hAB[j] += D.dd[i][j] * gAB[i];
            for (unsigned int K = 0; K < 3; ++K)
              for (unsigned int L = K; L < 3; ++L)
                {
                  const double sym_I =
                    0.5 * ((A == K) * (B == L) + (A == L) * (B == K));
                  T[A][B][K][L] =
                    4. * (hAB[0] * G[0][K][L] + hAB[1] * G[1][K][L] +
                          hAB[2] * G[2][K][L] +
                          D.d[1] * ((A == B) * (K == L) - sym_I) +
                          c3 * (C_inv[A][B] * C_inv[K][L] -
                                0.5 * (C_inv[A][K] * C_inv[B][L] +
                                       C_inv[A][L] * C_inv[B][K])));
                }
          }
    }
  } // namespace Materials
} // namespace TissueContact
