#include <tissue_contact/materials/isotropic_material.h>

namespace TissueContact
{
  namespace Materials
  {
    namespace
    {
      // (I (x) I - II)_pq in Voigt form: 1 - 1 = 0 on the normal diagonal, 1
      // between two normal entries, -1/2 on the shear diagonal, 0 elsewhere
      constexpr double I_minus_II[6][6] = {{0., 1., 1., 0., 0., 0.},
                                           {1., 0., 1., 0., 0., 0.},
                                           {1., 1., 0., 0., 0., 0.},
                                           {0., 0., 0., -0.5, 0., 0.},
                                           {0., 0., 0., 0., -0.5, 0.},
                                           {0., 0., 0., 0., 0., -0.5}};

      /** (X x X - X (.) X)_pq in Voigt form, X symmetric; I_minus_II for
       * X = I. */
      double
      cross_term(const double (&X)[3][3],
                 const unsigned int p,
                 const unsigned int q)
      {
        const auto        &index = VoigtTangent::index;
        const unsigned int A = index[p][0], B = index[p][1];
        const unsigned int K = index[q][0], L = index[q][1];
        return X[A][B] * X[K][L] -
               0.5 * (X[A][K] * X[B][L] + X[A][L] * X[B][K]);
      }

      /**
       * (M3V), and with pushed-forward tensors (M3S): the 21 entries p <= q
       * of 4 [sum_ij Psi_ij G_i x G_j + Psi_2 (X2 x X2 - X2 (.) X2) +
       * Psi_3 I3 (X3 x X3 - X3 (.) X3)], mirrored, each in closed form;
       * a null X2 or X3 stands for I (the constant table).
       */
      void
      voigt_closed_form(const SymmetricTensor<2, 3> (&G)[3],
                        const InvariantDerivatives  &Psi,
                        const double                 I3,
                        const SymmetricTensor<2, 3> *X2,
                        const SymmetricTensor<2, 3> *X3,
                        VoigtTangent                &out)
      {
        const auto  &index = VoigtTangent::index;
        auto        &D     = out.D;
        const double c3    = Psi.d[2] * I3;
        double       x2[3][3], x3[3][3]; // as plain arrays (cheap to index)
        for (unsigned int A = 0; A < 3; ++A)
          for (unsigned int B = 0; B < 3; ++B)
            {
              x2[A][B] = X2 != nullptr ? (*X2)[A][B] : 0.;
              x3[A][B] = X3 != nullptr ? (*X3)[A][B] : 0.;
            }
        double g[3][6], h[3][6]; // h_j,p = sum_i Psi_ij G_i,p
        for (unsigned int p = 0; p < 6; ++p)
          {
            const unsigned int A = index[p][0], B = index[p][1];
            for (unsigned int i = 0; i < 3; ++i)
              g[i][p] = G[i][A][B];
            for (unsigned int j = 0; j < 3; ++j)
              h[j][p] = 0.;
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int j = 0; j < 3; ++j)
                h[j][p] += Psi.dd[i][j] * g[i][p];
          }
        for (unsigned int p = 0; p < 6; ++p)
          for (unsigned int q = p; q < 6; ++q)
            D[p][q] = D[q][p] =
              4. *
              (h[0][p] * g[0][q] + h[1][p] * g[1][q] + h[2][p] * g[2][q] +
               Psi.d[1] *
                 (X2 != nullptr ? cross_term(x2, p, q) : I_minus_II[p][q]) +
               c3 * (X3 != nullptr ? cross_term(x3, p, q) : I_minus_II[p][q]));
      }
    } // namespace


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
                                VoigtTangent          *CC) const
    {
      const Invariants            I     = invariants(C);
      const InvariantDerivatives  Psi   = psi_derivatives(I);
      const SymmetricTensor<2, 3> Id    = unit_symmetric_tensor<3>();
      const SymmetricTensor<2, 3> C_inv = invert(C);

      // G_i = dI_i/dC
      const SymmetricTensor<2, 3> G[3] = {Id, I.I1 * Id - C, I.I3 * C_inv};

      S = 2. * (Psi.d[0] * G[0] + Psi.d[1] * G[1] + Psi.d[2] * G[2]);

      if (CC != nullptr)
        // (M3):
        // sum_ij Psi_ij G_i x G_j
        //   + Psi_2 (I x I - II)                          [d^2 I2 / dC dC]
        //   + Psi_3 I3 (C^-1 x C^-1 - C^-1 (.) C^-1)      [d^2 I3 / dC dC]
        voigt_closed_form(G, Psi, I.I3, nullptr, &C_inv, *CC);
    }


    void
    IsotropicMaterial::stress_b(const Tensor<2, 3> &F,
                                const Point<3> &,
                                SymmetricTensor<2, 3> &tau,
                                VoigtTangent          *c) const
    {
      // b = F F^T and b^2; the invariants of b are those of C
      const SymmetricTensor<2, 3> b   = symmetrize(F * transpose(F));
      const Invariants            I   = invariants(b);
      const InvariantDerivatives  Psi = psi_derivatives(I);
      const SymmetricTensor<2, 3> Id  = unit_symmetric_tensor<3>();
      SymmetricTensor<2, 3>       b2; // b b (b * b contracts both indices)
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          b2[i][j] = b[i][0] * b[0][j] + b[i][1] * b[1][j] + b[i][2] * b[2][j];

      // g_i = F G_i F^T (M3S)
      const SymmetricTensor<2, 3> g[3] = {b, I.I1 * b - b2, I.I3 * Id};

      tau = 2. * (Psi.d[0] * g[0] + Psi.d[1] * g[1] + Psi.d[2] * g[2]);

      if (c != nullptr)
        // (M3S): (M3) with I, C, C^-1 replaced by b, b^2, I
        voigt_closed_form(g, Psi, I.I3, &b, nullptr, *c);
    }
  } // namespace Materials
} // namespace TissueContact
