#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <vector>

namespace TissueContact
{
  namespace Elasticity
  {
    using namespace dealii;

    /**
     * One element of the single-rotation formulation (tet10SR,
     * doc/theory/10-single-rotation.md): linear elasticity in the frame of
     * the rotation @f$R@f$ of the polar decomposition of the corner
     * vertices' deformation gradient
     * @f$F_c = \sum_{a<4} x_a\otimes\nabla\lambda_a@f$,
     * @f$\Pi_e = \frac12 d^TK_ed@f$ with @f$d_I = R^Tx_I - X_I@f$ (SR1), its
     * exact gradient (SR4) and Hessian (SR5). Local index of node @p I,
     * component @p i: @f$3I + i@f$; nodes 0..3 are the corners. The element
     * does not own its data: it views a stiffness matrix, reference
     * positions and corner gradients stored by the caller.
     */
    class SingleRotationElement
    {
    public:
      /**
       * @p K: the @f$3n\times 3n@f$ linear-elastic stiffness (row major),
       * @p X: the @p n_nodes reference positions, @p grad_lambda: the four
       * reference gradients @f$\nabla\lambda_a@f$ of the corners.
       */
      SingleRotationElement(const unsigned int  n_nodes,
                            const double       *K,
                            const Point<3>     *X,
                            const Tensor<1, 3> *grad_lambda);

      /**
       * The linear-elastic stiffness
       * @f$K_{Ii,Jk} = \sum_q w_q(\lambda\,g_{Ii}g_{Jk} +
       * \mu(g_I\cdot g_J\delta_{ik} + g_{Ik}g_{Ji}))@f$ from the shape
       * gradients @p grad_N[q * n_nodes + I] and weights @p JxW[q],
       * written to @p K (@f$3n\times3n@f$, row major).
       */
      static void
      stiffness(const unsigned int  n_nodes,
                const unsigned int  n_q,
                const Tensor<1, 3> *grad_N,
                const double       *JxW,
                const double        mu,
                const double        lambda,
                double             *K);

      /** The corner gradients of the reference tetrahedron with vertices
       * @p X[0..3]. */
      static void
      corner_gradients(const Point<3> *X, Tensor<1, 3> *grad_lambda);

      /** @f$F_c@f$ at the current positions @p x. */
      Tensor<2, 3>
      corner_deformation_gradient(const Point<3> *x) const;

      /**
       * @f$\Pi_e@f$ at the current positions @p x; false, leaving
       * @p energy unset, if @f$\det F_c \le 0@f$.
       */
      bool
      energy(const Point<3> *x, double &energy) const;

      /**
       * The gradient @p r (@f$3n@f$) and, when @p H is not null, the
       * Hessian (@f$3n\times3n@f$, row major) at @p x; false if
       * @f$\det F_c \le 0@f$.
       */
      bool
      gradient(const Point<3> *x, double *r, double *H) const;

    private:
      const unsigned int  n_nodes;
      const double       *K;
      const Point<3>     *X;
      const Tensor<1, 3> *grad_lambda;
    };
  } // namespace Elasticity
} // namespace TissueContact
