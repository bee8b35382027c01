#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <array>

namespace TissueContact
{
  namespace Materials
  {
    using namespace dealii;

    /**
     * The material elasticity tensor
     * @f$\mathbb{C}_{IJKL} = \partial S_{IJ}/\partial E_{KL}@f$ (minor and
     * major symmetries) as the symmetric 6 x 6 matrix
     * @f$D_{pq} = \mathbb{C}_{I_pJ_pK_qL_q}@f$ in the Voigt order 11 22 33
     * 23 13 12 (doc/theory/03-materials.md, sec. 3.1, (M3V)). No factor 2
     * on the shear rows: the strain-displacement matrix @f$B_a@f$ of the
     * assembly carries the engineering shears
     * (doc/theory/02-weak-form-and-linearization.md). A model writes its
     * tangent here entry by entry in closed form; the assembly reads the
     * 6 x 6 matrix as it is.
     */
    struct VoigtTangent
    {
      /** The index pairs (I_p, J_p) of the Voigt order. */
      static constexpr unsigned int index[6][2] =
        {{0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};

      std::array<std::array<double, 6>, 6> D{};

      /** The Voigt vector @f$a_p = a_{I_pJ_p}@f$ of a symmetric tensor. */
      static std::array<double, 6>
      vector(const SymmetricTensor<2, 3> &a)
      {
        std::array<double, 6> v;
        for (unsigned int p = 0; p < 6; ++p)
          v[p] = a[index[p][0]][index[p][1]];
        return v;
      }

      /** @f$D \mathrel{+}= c\, a\otimes b@f$, i.e.
       * @f$D_{pq} \mathrel{+}= c\,(a_p b_q)@f$ for all 36 entries. */
      void
      add_outer(const double                 c,
                const SymmetricTensor<2, 3> &a,
                const SymmetricTensor<2, 3> &b)
      {
        const auto va = vector(a), vb = vector(b);
        for (unsigned int p = 0; p < 6; ++p)
          for (unsigned int q = 0; q < 6; ++q)
            D[p][q] += c * (va[p] * vb[q]);
      }

      /** Copy the upper triangle into the lower one: a sum of terms
       * @f$a\otimes b@f$ that is symmetric only as a whole is so only up to
       * rounding entry by entry. */
      void
      mirror_upper()
      {
        for (unsigned int p = 0; p < 6; ++p)
          for (unsigned int q = p + 1; q < 6; ++q)
            D[q][p] = D[p][q];
      }

      /** The tensor @f$\mathbb{C}_{IJKL}@f$ with all 81 components. */
      Tensor<4, 3>
      tensor() const
      {
        unsigned int p_of[3][3];
        for (unsigned int p = 0; p < 6; ++p)
          p_of[index[p][0]][index[p][1]] = p_of[index[p][1]][index[p][0]] = p;
        Tensor<4, 3> CC;
        for (unsigned int I = 0; I < 3; ++I)
          for (unsigned int J = 0; J < 3; ++J)
            for (unsigned int K = 0; K < 3; ++K)
              for (unsigned int L = 0; L < 3; ++L)
                CC[I][J][K][L] = D[p_of[I][J]][p_of[K][L]];
        return CC;
      }
    };
  } // namespace Materials
} // namespace TissueContact
