#pragma once

#include <tissue_contact/contact/triangle_tetrahedron_intersection.h>

#include <deal.II/differentiation/ad/ad_number_traits.h>
#include <deal.II/differentiation/ad/sacado_number_types.h>
#include <deal.II/differentiation/ad/sacado_product_types.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <functional>
#include <vector>

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

    /** The number type of the reference derivatives: Sacado forward mode
     * over forward mode, exact first and second derivatives. */
    using ADNumber = Differentiation::AD::NumberTraits<
      double,
      Differentiation::AD::NumberTypes::sacado_dfad_dfad>::ad_type;

    /** Value, gradient and Hessian of @p energy at @p coordinates by
     * automatic differentiation (deal.II's Differentiation::AD helper). */
    PairDerivatives
    differentiate(
      const std::vector<double>                                    &coordinates,
      const std::function<ADNumber(const std::vector<ADNumber> &)> &energy);

    /** First-order AD number: gradients only (the residual). */
    using ADNumber1 = Differentiation::AD::NumberTraits<
      double,
      Differentiation::AD::NumberTypes::sacado_dfad>::ad_type;

    /** Value and gradient only (hessian left empty), by first-order AD:
     * about n times cheaper than differentiate() for n coordinates. */
    PairDerivatives
    differentiate_once(
      const std::vector<double> &coordinates,
      const std::function<ADNumber1(const std::vector<ADNumber1> &)> &energy);

    /**
     * Value, gradient and (if @p with_hessian) Hessian with respect to the
     * 21 coordinates (tetrahedron vertices, then triangle vertices) of a
     * pair energy @p energy(tet, tri), a generic callable templated on the
     * number type, by automatic differentiation.
     */
    template <typename PairEnergy>
    PairDerivatives
    differentiate_pair(const std::array<Point<3>, 4> &tet,
                       const std::array<Point<3>, 3> &tri,
                       const bool                     with_hessian,
                       const PairEnergy              &energy)
    {
      std::vector<double> coordinates;
      for (const auto &p : tet)
        for (unsigned int d = 0; d < 3; ++d)
          coordinates.push_back(p[d]);
      for (const auto &p : tri)
        for (unsigned int d = 0; d < 3; ++d)
          coordinates.push_back(p[d]);
      const auto unpack = [&](const auto &x) {
        using Number = typename std::decay_t<decltype(x)>::value_type;
        std::array<Point<3, Number>, 4> tet_ad;
        std::array<Point<3, Number>, 3> tri_ad;
        for (unsigned int v = 0; v < 4; ++v)
          for (unsigned int d = 0; d < 3; ++d)
            tet_ad[v][d] = x[3 * v + d];
        for (unsigned int v = 0; v < 3; ++v)
          for (unsigned int d = 0; d < 3; ++d)
            tri_ad[v][d] = x[12 + 3 * v + d];
        return energy(tet_ad, tri_ad);
      };
      if (with_hessian)
        return differentiate(coordinates, unpack);
      return differentiate_once(coordinates, unpack);
    }

    PairDerivatives
    penalty_derivatives_ad(const std::array<Point<3>, 4> &tet,
                           const std::array<Point<3>, 3> &tri,
                           const std::array<double, 4>   &g,
                           const double                   eps_p,
                           const bool                     with_hessian = true);
  } // namespace Contact
} // namespace TissueContact
