#include <tissue_contact/materials/material.h>

#include <deal.II/base/exceptions.h>

namespace TissueContact
{
  namespace Materials
  {
    void
    push_forward_tangent(const Tensor<2, 3> &F,
                         const Tensor<2, 3> &S,
                         const Tensor<4, 3> &CC,
                         Tensor<2, 3>       &P,
                         Tensor<4, 3>       &A)
    {
      P = F * S;
      // T_iJLN = F_iI CC_IJLN
      Tensor<4, 3> T;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int J = 0; J < 3; ++J)
          for (unsigned int L = 0; L < 3; ++L)
            for (unsigned int N = 0; N < 3; ++N)
              T[i][J][L][N] = F[i][0] * CC[0][J][L][N] +
                              F[i][1] * CC[1][J][L][N] +
                              F[i][2] * CC[2][J][L][N];
      // A_iJkL = delta_ik S_JL + T_iJLN F_kN
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int J = 0; J < 3; ++J)
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int L = 0; L < 3; ++L)
              A[i][J][k][L] = (i == k ? S[J][L] : 0.) +
                              T[i][J][L][0] * F[k][0] +
                              T[i][J][L][1] * F[k][1] + T[i][J][L][2] * F[k][2];
    }


    void
    check_stable_lame_parameters(const std::string &model,
                                 const double       mu,
                                 const double       lambda)
    {
      AssertThrow(std::isfinite(mu) && mu > 0.,
                  ExcMessage("material '" + model +
                             "': the parameters give a small-strain shear "
                             "modulus mu = " +
                             std::to_string(mu) +
                             " <= 0; use positive stiffness parameters"));
      AssertThrow(std::isfinite(lambda) && lambda + 2. / 3. * mu > 0.,
                  ExcMessage("material '" + model +
                             "': the parameters give a small-strain bulk "
                             "modulus lambda + 2/3 mu = " +
                             std::to_string(lambda + 2. / 3. * mu) +
                             " <= 0; increase the compressibility parameter"));
    }
  } // namespace Materials
} // namespace TissueContact
