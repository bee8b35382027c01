#pragma once

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>
#include <tissue_contact/contact/triangle_tetrahedron_intersection.h>

namespace TissueContact
{
  namespace Contact
  {
    /**
     * The penalty energy of one triangle-tetrahedron pair (dissertation
     * 5.4.6, paper 5.3; doc/theory/05-contact.md, sec. 3):
     * @f[ W = \frac{\varepsilon_p}{2}\int_{T\cap K} g^2\,da, \qquad
     *     g(x) = \sum_{j=0}^{3} \lambda_j(x)\, g_j, @f]
     * with the material depths @f$g_j@f$ of the tetrahedron's vertices and
     * the current positions. The polygon @f$T\cap K@f$ is fanned into
     * triangles; g is linear on each, so with its corner values
     * @f$G_1, G_2, G_3@f$ and area A the integral is exact:
     * @f$W = \varepsilon_p\frac{A}{12}(G_1^2 + G_2^2 + G_3^2 + G_1G_2 +
     * G_2G_3 + G_3G_1)@f$. Fan triangles of (numerically) zero area are
     * skipped: their contribution vanishes, and the derivative of
     * @f$|n|@f$ at @f$n = 0@f$ would not be finite.
     */
    template <typename Number>
    Number
    penalty_energy(const std::array<Point<3, Number>, 4> &tet,
                   const std::array<Point<3, Number>, 3> &tri,
                   const std::array<double, 4>           &g,
                   const double                           eps_p)
    {
      using Traits = Differentiation::AD::ADNumberTraits<Number>;
      const IntersectionPolygon<Number> polygon = intersect(tet, tri);
      Number                            W(0.);
      if (polygon.n_vertices < 3)
        return W;

      // zero-area threshold from the triangle's size
      double L2 = 0.;
      for (unsigned int k = 0; k < 3; ++k)
        L2 = std::max(L2,
                      Traits::get_scalar_value(
                        (tri[(k + 1) % 3] - tri[k]).norm_square()));
      const double tiny = 1e-28 * L2 * L2;

      std::array<Number, 8> G;
      for (unsigned int k = 0; k < polygon.n_vertices; ++k)
        {
          G[k] = Number(0.);
          for (unsigned int j = 0; j < 4; ++j)
            G[k] += polygon.vertex[k].lambda[j] * g[j];
        }
      const auto &x = polygon.vertex;
      for (unsigned int k = 1; k + 1 < polygon.n_vertices; ++k)
        {
          const Tensor<1, 3, Number> n =
            cross_product_3d(x[k].x - x[0].x, x[k + 1].x - x[0].x);
          const Number n2 = n.norm_square();
          if (!(Traits::get_scalar_value(n2) > tiny))
            continue;
          const Number A = 0.5 * std::sqrt(n2);
          W += eps_p * A / 12. *
               (G[0] * G[0] + G[k] * G[k] + G[k + 1] * G[k + 1] + G[0] * G[k] +
                G[k] * G[k + 1] + G[k + 1] * G[0]);
        }
      return W;
    }

    /** Area of the intersection of the triangle with the tetrahedron. */
    double
    intersection_area(const std::array<Point<3>, 4> &tet,
                      const std::array<Point<3>, 3> &tri);

    /**
     * Energy, gradient (21 entries: the 4 tetrahedron vertices, then the 3
     * triangle vertices, x y z each) and Hessian (21 x 21) of
     * penalty_energy(), exact derivatives of the discrete energy by
     * automatic differentiation (Sacado, forward over forward, through
     * deal.II's Differentiation::AD). The reference kernel.
     */
    struct PairDerivatives
    {
      double             energy = 0.;
      Vector<double>     gradient;
      FullMatrix<double> hessian;
    };

    PairDerivatives
    penalty_derivatives_ad(const std::array<Point<3>, 4> &tet,
                           const std::array<Point<3>, 3> &tri,
                           const std::array<double, 4>   &g,
                           const double                   eps_p);
  } // namespace Contact
} // namespace TissueContact
