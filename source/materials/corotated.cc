#include <tissue_contact/materials/corotated.h>

#include <cmath>

namespace TissueContact
{
  namespace Materials
  {
    namespace
    {
      /** The principal stretches @f$\lambda_i@f$ (square roots of the
       * eigenvalues of @p C) and the unit eigenvectors @f$n_i@f$. */
      std::array<std::pair<double, Tensor<1, 3>>, 3>
      principal_stretches(const SymmetricTensor<2, 3> &C)
      {
        auto e = eigenvectors(C, SymmetricTensorEigenvectorMethod::jacobi);
        for (auto &[value, n] : e)
          value = std::sqrt(std::max(value, 0.));
        return e;
      }


      /** @f$M_{ij} = \frac12(n_i\otimes n_j + n_j\otimes n_i)@f$. */
      SymmetricTensor<2, 3>
      basis(const Tensor<1, 3> &a, const Tensor<1, 3> &b)
      {
        SymmetricTensor<2, 3> M;
        for (unsigned int r = 0; r < 3; ++r)
          for (unsigned int c = r; c < 3; ++c)
            M[r][c] = 0.5 * (a[r] * b[c] + b[r] * a[c]);
        return M;
      }
    } // namespace


    Corotated::Corotated(const double mu, const double lambda)
      : mu(mu)
      , lambda(lambda)
    {
      check_stable_lame_parameters(name(), mu, lambda);
    }


    double
    Corotated::energy_C(const SymmetricTensor<2, 3> &C, const Point<3> &) const
    {
      const auto e   = principal_stretches(C);
      double     sq  = 0.;
      double     tau = 0.;
      for (const auto &[l, n] : e)
        {
          sq += (l - 1.) * (l - 1.);
          tau += l - 1.;
        }
      return mu * sq + 0.5 * lambda * tau * tau;
    }


    void
    Corotated::stress_C(const SymmetricTensor<2, 3> &C,
                        const Point<3> &,
                        SymmetricTensor<2, 3> &S,
                        VoigtTangent          *CC) const
    {
      const auto   e   = principal_stretches(C);
      const double tau = e[0].first + e[1].first + e[2].first - 3.;
      std::array<SymmetricTensor<2, 3>, 3> M_ii;
      S = SymmetricTensor<2, 3>();
      for (unsigned int i = 0; i < 3; ++i)
        {
          const auto &[l, n] = e[i];
          M_ii[i]            = basis(n, n);
          // (M6): S = U^{-1} T, t_i = 2 mu (lambda_i - 1) + lambda tau
          S += (2. * mu * (l - 1.) + lambda * tau) / l * M_ii[i];
        }
      if (CC == nullptr)
        return;
      // (M7)
      *CC              = VoigtTangent();
      const double top = 2. * mu - lambda * tau;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          {
            const double li = e[i].first, lj = e[j].first;
            const double c = top / (li * lj * (li + lj));
            if (i == j)
              CC->add_outer(2. * c, M_ii[i], M_ii[i]);
            else
              {
                const SymmetricTensor<2, 3> M = basis(e[i].second, e[j].second);
                CC->add_outer(4. * c, M, M);
              }
          }
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int k = 0; k < 3; ++k)
          CC->add_outer(lambda / (e[i].first * e[k].first), M_ii[i], M_ii[k]);
      CC->mirror_upper();
    }
  } // namespace Materials
} // namespace TissueContact
