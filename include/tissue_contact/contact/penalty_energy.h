#pragma once

#include <tissue_contact/contact/triangle_tetrahedron_intersection.h>

#include <deal.II/differentiation/ad/ad_number_traits.h>

namespace TissueContact
{
  namespace Contact
  {
    /**
     * @f$\int_P g^2\,da@f$ over a planar convex polygon P with vertices
     * @p x and values @p G of a function g that is linear on P: fan P
     * into triangles @f$(x_0, x_k, x_{k+1})@f$; on one with corner values
     * @f$G_0, G_k, G_{k+1}@f$ the integral is exactly
     * @f$\frac{\ell_k}{12}(G_0^2 + G_k^2 + G_{k+1}^2 + G_0G_k + G_kG_{k+1}
     * + G_{k+1}G_0)@f$ with twice its area
     * @f$\ell_k = n_k\cdot\nu@f$, @f$n_k = (x_k - x_0)\times(x_{k+1} -
     * x_0)@f$ and @p nu the unit normal of the polygon's plane, oriented
     * with its vertex order (doc/theory/05-contact.md, sec. 4). For a
     * convex polygon @f$\ell_k = |n_k|@f$; unlike @f$|n_k|@f$, the signed
     * form is a polynomial in the vertices, so a sliver (a fan triangle of
     * rounding-level area, which degenerate positions produce) has bounded
     * derivatives instead of a Hessian of order @f$1/|n_k|@f$.
     */
    template <typename Number, std::size_t N>
    Number
    integral_of_square(const std::array<Point<3, Number>, N> &x,
                       const std::array<Number, N>           &G,
                       const unsigned int                     n_vertices,
                       const Tensor<1, 3, Number>            &nu)
    {
      Number integral(0.);
      for (unsigned int k = 1; k + 1 < n_vertices; ++k)
        integral += (cross_product_3d(x[k] - x[0], x[k + 1] - x[0]) * nu) /
                    12. *
                    (G[0] * G[0] + G[k] * G[k] + G[k + 1] * G[k + 1] +
                     G[0] * G[k] + G[k] * G[k + 1] + G[k + 1] * G[0]);
      return integral;
    }

    /** The unit normal of a triangle, oriented by its vertex order. */
    template <typename Number>
    Tensor<1, 3, Number>
    unit_normal(const std::array<Point<3, Number>, 3> &tri)
    {
      const Tensor<1, 3, Number> N =
        cross_product_3d(tri[1] - tri[0], tri[2] - tri[0]);
      const Number length = std::sqrt(N.norm_square());
      return N / length;
    }

    /**
     * The penalty energy of one triangle-tetrahedron pair (dissertation
     * 5.4.6, paper 5.3; doc/theory/05-contact.md, sec. 4):
     * @f[ W = \frac{\varepsilon_p}{2}\int_{T\cap K} g^2\,da, \qquad
     *     g(x) = \sum_{j=0}^{3} \lambda_j(x)\, g_j, @f]
     * with the material depths @f$g_j@f$ of the tetrahedron's vertices and
     * the current positions; g is linear on the polygon @f$T\cap K@f$, so
     * integral_of_square() is exact.
     */
    template <typename Number>
    Number
    penalty_energy(const std::array<Point<3, Number>, 4> &tet,
                   const std::array<Point<3, Number>, 3> &tri,
                   const std::array<double, 4>           &g,
                   const double                           eps_p)
    {
      const IntersectionPolygon<Number> polygon = intersect(tet, tri);
      if (polygon.n_vertices < 3)
        return Number(0.);
      std::array<Point<3, Number>, 9> x;
      std::array<Number, 9>           G;
      for (unsigned int k = 0; k < polygon.n_vertices; ++k)
        {
          x[k] = polygon.vertex[k].x;
          G[k] = Number(0.);
          for (unsigned int j = 0; j < 4; ++j)
            G[k] += polygon.vertex[k].lambda[j] * g[j];
        }
      // the clipping keeps the triangle's vertex order
      return 0.5 * eps_p *
             integral_of_square(x, G, polygon.n_vertices, unit_normal(tri));
    }

    /** penalty_energy() in double precision, compiled also for AVX-512 and
     * AVX2 (base/multiversion.h): the same bits, what the assembler's energy
     * evaluations (line search, sparsity check) call. */
    double
    penalty_energy_value(const std::array<Point<3>, 4> &tet,
                         const std::array<Point<3>, 3> &tri,
                         const std::array<double, 4>   &g,
                         const double                   eps_p);

    /** Area of the intersection of the triangle with the tetrahedron. */
    double
    intersection_area(const std::array<Point<3>, 4> &tet,
                      const std::array<Point<3>, 3> &tri);

  } // namespace Contact
} // namespace TissueContact
