#include <tissue_contact/base/cross_matrix.h>
#include <tissue_contact/base/polar_rotation.h>

#include <cmath>

namespace TissueContact
{
  PolarRotation::PolarRotation(const Tensor<2, 3> &F)
  {
    // C = F^T F = sum_i lambda_i^2 n_i (x) n_i, U = sum_i lambda_i n_i (x) n_i
    const auto            e = eigenvectors(symmetrize(transpose(F) * F),
                                SymmetricTensorEigenvectorMethod::jacobi);
    SymmetricTensor<2, 3> U_inverse;
    for (unsigned int i = 0; i < 3; ++i)
      {
        const double lambda = std::sqrt(std::max(e[i].first, 0.));
        const SymmetricTensor<2, 3> nn =
          symmetrize(outer_product(e[i].second, e[i].second));
        stretch += lambda * nn;
        U_inverse += (1. / lambda) * nn;
      }
    rotation = F * static_cast<Tensor<2, 3>>(U_inverse);
    // M = tr(U) I - U, eigenvalues lambda_j + lambda_k > 0
    const Tensor<2, 3> M =
      trace(stretch) * unit_symmetric_tensor<3>() - stretch;
    M_inverse = invert(M);
  }


  Tensor<1, 3>
  PolarRotation::axial(const Tensor<2, 3> &W)
  {
    return Tensor<1, 3>({W[2][1], W[0][2], W[1][0]});
  }


  Tensor<1, 3>
  PolarRotation::omega(const Tensor<2, 3> &dF) const
  {
    const Tensor<2, 3> A = transpose(rotation) * dF;
    return M_inverse * axial(A - transpose(A));
  }


  Tensor<2, 3>
  PolarRotation::dR(const Tensor<2, 3> &dF) const
  {
    return rotation * cross_matrix(omega(dF));
  }


  Tensor<2, 3>
  PolarRotation::Rt_d2R(const Tensor<2, 3> &dF1,
                        const Tensor<1, 3> &omega1,
                        const Tensor<2, 3> &dF2,
                        const Tensor<1, 3> &omega2) const
  {
    const Tensor<2, 3> W2 = cross_matrix(omega2);
    // dU_2 = R^T dF_2 - W_2 U; d(axial(R^T dF_1 - dF_1^T R)) along dF_2
    const Tensor<2, 3> dU2 =
      transpose(rotation) * dF2 - W2 * static_cast<Tensor<2, 3>>(stretch);
    const Tensor<2, 3> A  = W2 * transpose(rotation) * dF1;
    const Tensor<1, 3> da = axial(transpose(A) - A);
    const Tensor<1, 3> domega1 =
      M_inverse * (da - (trace(dU2) * omega1 - dU2 * omega1));
    return W2 * cross_matrix(omega1) + cross_matrix(domega1);
  }


  Tensor<2, 3>
  PolarRotation::d2R(const Tensor<2, 3> &dF1, const Tensor<2, 3> &dF2) const
  {
    return rotation * Rt_d2R(dF1, omega(dF1), dF2, omega(dF2));
  }
} // namespace TissueContact
