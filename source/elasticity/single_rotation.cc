#include <tissue_contact/base/cross_matrix.h>
#include <tissue_contact/base/polar_rotation.h>
#include <tissue_contact/elasticity/single_rotation.h>

#include <array>

namespace TissueContact
{
  namespace Elasticity
  {
    namespace
    {
      // n <= 10 nodes: 30 local unknowns at most
      constexpr unsigned int max_local = 30;
    } // namespace


    SingleRotationElement::SingleRotationElement(
      const unsigned int  n_nodes,
      const double       *K,
      const Point<3>     *X,
      const Tensor<1, 3> *grad_lambda)
      : n_nodes(n_nodes)
      , K(K)
      , X(X)
      , grad_lambda(grad_lambda)
    {
      AssertThrow(n_nodes >= 4 && 3 * n_nodes <= max_local,
                  ExcNotImplemented());
    }


    void
    SingleRotationElement::stiffness(const unsigned int  n_nodes,
                                     const unsigned int  n_q,
                                     const Tensor<1, 3> *grad_N,
                                     const double       *JxW,
                                     const double        mu,
                                     const double        lambda,
                                     double             *K)
    {
      const unsigned int n3 = 3 * n_nodes;
      std::fill(K, K + n3 * n3, 0.);
      for (unsigned int q = 0; q < n_q; ++q)
        {
          const Tensor<1, 3> *g = grad_N + q * n_nodes;
          for (unsigned int I = 0; I < n_nodes; ++I)
            for (unsigned int J = 0; J < n_nodes; ++J)
              {
                const double gg = g[I] * g[J];
                for (unsigned int i = 0; i < 3; ++i)
                  for (unsigned int k = 0; k < 3; ++k)
                    K[(3 * I + i) * n3 + 3 * J + k] +=
                      JxW[q] * (lambda * g[I][i] * g[J][k] +
                                mu * ((i == k ? gg : 0.) + g[I][k] * g[J][i]));
              }
        }
    }


    void
    SingleRotationElement::corner_gradients(const Point<3> *X,
                                            Tensor<1, 3>   *grad_lambda)
    {
      // lambda_a(X) for a = 1..3 are the rows of D^-1 applied to X - X_0,
      // D = [X_1 - X_0, X_2 - X_0, X_3 - X_0]
      Tensor<2, 3> D;
      for (unsigned int a = 1; a < 4; ++a)
        for (unsigned int i = 0; i < 3; ++i)
          D[i][a - 1] = X[a][i] - X[0][i];
      const Tensor<2, 3> Di = invert(D);
      grad_lambda[0]        = Tensor<1, 3>();
      for (unsigned int a = 1; a < 4; ++a)
        {
          grad_lambda[a] = Di[a - 1];
          grad_lambda[0] -= Di[a - 1];
        }
    }


    Tensor<2, 3>
    SingleRotationElement::corner_deformation_gradient(const Point<3> *x) const
    {
      Tensor<2, 3> F;
      for (unsigned int a = 0; a < 4; ++a)
        F += outer_product(static_cast<Tensor<1, 3>>(x[a]), grad_lambda[a]);
      return F;
    }


    bool
    SingleRotationElement::energy(const Point<3> *x, double &energy) const
    {
      const Tensor<2, 3> F = corner_deformation_gradient(x);
      if (!(determinant(F) > 0.))
        return false;
      const Tensor<2, 3>            Rt = transpose(PolarRotation(F).R());
      const unsigned int            n3 = 3 * n_nodes;
      std::array<double, max_local> d;
      for (unsigned int I = 0; I < n_nodes; ++I)
        {
          const Tensor<1, 3> dI = Rt * x[I] - X[I];
          for (unsigned int i = 0; i < 3; ++i)
            d[3 * I + i] = dI[i];
        }
      energy = 0.;
      for (unsigned int p = 0; p < n3; ++p)
        {
          double Kd = 0.;
          for (unsigned int q = 0; q < n3; ++q)
            Kd += K[p * n3 + q] * d[q];
          energy += 0.5 * d[p] * Kd;
        }
      return true;
    }


    bool
    SingleRotationElement::gradient(const Point<3> *x,
                                    double         *r,
                                    double         *H) const
    {
      const Tensor<2, 3> F = corner_deformation_gradient(x);
      if (!(determinant(F) > 0.))
        return false;
      const PolarRotation polar(F);
      const Tensor<2, 3> &R  = polar.R();
      const Tensor<2, 3>  Rt = transpose(R);
      const unsigned int  n3 = 3 * n_nodes;

      // y_I = R^T x_I, d = y - X, f = K d   (SR1)
      std::array<Tensor<1, 3>, max_local / 3> y, f;
      std::array<double, max_local>           d;
      for (unsigned int I = 0; I < n_nodes; ++I)
        {
          y[I] = Rt * x[I];
          for (unsigned int i = 0; i < 3; ++i)
            d[3 * I + i] = y[I][i] - X[I][i];
        }
      for (unsigned int I = 0; I < n_nodes; ++I)
        for (unsigned int i = 0; i < 3; ++i)
          {
            double v = 0.;
            for (unsigned int q = 0; q < n3; ++q)
              v += K[(3 * I + i) * n3 + q] * d[q];
            f[I][i] = v;
          }
      // R^T G = sum_I y_I (x) f_I
      Tensor<2, 3> RtG;
      for (unsigned int I = 0; I < n_nodes; ++I)
        RtG += outer_product(y[I], f[I]);

      // omega of the unit directions e_i (x) e_j, and of the corner
      // unknowns (a, i): dF = e_i (x) grad lambda_a   (SR2)
      std::array<std::array<Tensor<1, 3>, 3>, 3> Omega;
      std::array<std::array<Tensor<2, 3>, 3>, 3> E;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          {
            E[i][j][i][j] = 1.;
            Omega[i][j]   = polar.omega(E[i][j]);
          }
      std::array<Tensor<1, 3>, 12> omega;
      for (unsigned int a = 0; a < 4; ++a)
        for (unsigned int i = 0; i < 3; ++i)
          {
            omega[3 * a + i] = Tensor<1, 3>();
            for (unsigned int j = 0; j < 3; ++j)
              omega[3 * a + i] += grad_lambda[a][j] * Omega[i][j];
          }

      // (SR4): r_J = R f_J + [J corner] dR/dx_J : G, dR : G = [omega]_x :
      // R^T G
      for (unsigned int J = 0; J < n_nodes; ++J)
        {
          const Tensor<1, 3> Rf = R * f[J];
          for (unsigned int k = 0; k < 3; ++k)
            r[3 * J + k] = Rf[k];
        }
      for (unsigned int c = 0; c < 12; ++c)
        r[c] += scalar_product(cross_matrix(omega[c]), RtG);
      if (H == nullptr)
        return true;

      // (SR5), first term: J_d^T K J_d, J_d = blockdiag(R^T) + Z with
      // Z[(I,m)][c] = (dR_c^T x_I)_m = -(omega_c x y_I)_m on the corners
      std::array<std::array<double, 12>, max_local> Z;
      for (unsigned int I = 0; I < n_nodes; ++I)
        for (unsigned int c = 0; c < 12; ++c)
          {
            const Tensor<1, 3> z = -cross_product_3d(omega[c], y[I]);
            for (unsigned int m = 0; m < 3; ++m)
              Z[3 * I + m][c] = z[m];
          }
      // A = K J_d
      std::array<std::array<double, max_local>, max_local> A;
      for (unsigned int p = 0; p < n3; ++p)
        {
          const double *Kp = K + p * n3;
          for (unsigned int J = 0; J < n_nodes; ++J)
            for (unsigned int k = 0; k < 3; ++k)
              A[p][3 * J + k] = Kp[3 * J] * R[k][0] + Kp[3 * J + 1] * R[k][1] +
                                Kp[3 * J + 2] * R[k][2];
          for (unsigned int c = 0; c < 12; ++c)
            {
              double v = 0.;
              for (unsigned int q = 0; q < n3; ++q)
                v += Kp[q] * Z[q][c];
              A[p][c] += v;
            }
        }
      // H = J_d^T A
      for (unsigned int I = 0; I < n_nodes; ++I)
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int col = 0; col < n3; ++col)
            H[(3 * I + i) * n3 + col] = R[i][0] * A[3 * I][col] +
                                        R[i][1] * A[3 * I + 1][col] +
                                        R[i][2] * A[3 * I + 2][col];
      for (unsigned int c = 0; c < 12; ++c)
        for (unsigned int col = 0; col < n3; ++col)
          {
            double v = 0.;
            for (unsigned int q = 0; q < n3; ++q)
              v += Z[q][c] * A[q][col];
            H[c * n3 + col] += v;
          }
      // second term: f_J . (dR_c^T e_k) = (R (omega_c x f_J))_k, and its
      // transpose
      for (unsigned int c = 0; c < 12; ++c)
        for (unsigned int J = 0; J < n_nodes; ++J)
          {
            const Tensor<1, 3> v = R * cross_product_3d(omega[c], f[J]);
            for (unsigned int k = 0; k < 3; ++k)
              {
                H[c * n3 + 3 * J + k] += v[k];
                H[(3 * J + k) * n3 + c] += v[k];
              }
          }
      // third term: d2R[dF_c, dF_e] : G = R^T d2R : R^T G, from the 81
      // second derivatives along the unit directions (SR3)
      std::array<std::array<double, 9>, 9> B;
      for (unsigned int ij = 0; ij < 9; ++ij)
        for (unsigned int kl = ij; kl < 9; ++kl)
          {
            const unsigned int i = ij / 3, j = ij % 3, k = kl / 3, l = kl % 3;
            B[ij][kl] = B[kl][ij] = scalar_product(
              polar.Rt_d2R(E[i][j], Omega[i][j], E[k][l], Omega[k][l]), RtG);
          }
      for (unsigned int a = 0; a < 4; ++a)
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int b = 0; b < 4; ++b)
            for (unsigned int k = 0; k < 3; ++k)
              {
                double v = 0.;
                for (unsigned int j = 0; j < 3; ++j)
                  for (unsigned int l = 0; l < 3; ++l)
                    v += grad_lambda[a][j] * grad_lambda[b][l] *
                         B[3 * i + j][3 * k + l];
                H[(3 * a + i) * n3 + 3 * b + k] += v;
              }
      return true;
    }
  } // namespace Elasticity
} // namespace TissueContact
