#pragma once

#include <algorithm>
#include <array>
#include <deal.II/base/point.h>
#include <deal.II/differentiation/ad/ad_number_traits.h>

namespace TissueContact
{
  namespace Contact
  {
    using namespace dealii;

    /** A vertex of the intersection polygon: its position and its
     * barycentric coordinates in the tetrahedron. */
    template <typename Number>
    struct PolygonVertex
    {
      Point<3, Number>      x;
      std::array<Number, 4> lambda;
    };

    /** The intersection of a triangle with a tetrahedron: a convex polygon
     * of at most 7 vertices (3 triangle vertices + one per clipping plane). */
    template <typename Number>
    struct IntersectionPolygon
    {
      std::array<PolygonVertex<Number>, 9> vertex;
      unsigned int                         n_vertices = 0;
    };

    /**
     * Clip the triangle @p tri by the four half-spaces
     * @f$\lambda_i \ge 0@f$ of the tetrahedron @p tet (Sutherland-Hodgman;
     * doc/theory/05-contact.md, sec. 3). The barycentric coordinates are
     * affine in position, so they are carried along: a new vertex on the
     * segment from p to q, cut by plane i, is
     * @f$p + t(q - p)@f$ with @f$t = \lambda_i(p)/(\lambda_i(p) -
     * \lambda_i(q))@f$, and the denominator is positive whenever the
     * segment crosses the plane: no division by zero, no NaN, in any
     * degenerate position. Vertices on a plane count as inside; repeated
     * vertices of degenerate cases give zero-area pieces.
     *
     * Templated on the number type so that automatic differentiation
     * (Sacado) runs through it; branches use the values only.
     */
    template <typename Number>
    IntersectionPolygon<Number>
    intersect(const std::array<Point<3, Number>, 4> &tet,
              const std::array<Point<3, Number>, 3> &tri)
    {
      using Traits     = Differentiation::AD::ADNumberTraits<Number>;
      const auto value = [](const Number &v) {
        return Traits::get_scalar_value(v);
      };

      // barycentric coordinates: lambda_1..3 = T^-1 (x - x0), with the
      // inverse written by cross products
      const Tensor<1, 3, Number> e1 = tet[1] - tet[0], e2 = tet[2] - tet[0],
                                 e3 = tet[3] - tet[0];
      const Tensor<1, 3, Number> n1 = cross_product_3d(e2, e3),
                                 n2 = cross_product_3d(e3, e1),
                                 n3 = cross_product_3d(e1, e2);
      const Number six_volume       = e1 * n1;

      IntersectionPolygon<Number> polygon, clipped;
      for (unsigned int k = 0; k < 3; ++k)
        {
          const Tensor<1, 3, Number> r = tri[k] - tet[0];
          PolygonVertex<Number>     &v = polygon.vertex[k];
          v.x                          = tri[k];
          v.lambda[1]                  = (r * n1) / six_volume;
          v.lambda[2]                  = (r * n2) / six_volume;
          v.lambda[3]                  = (r * n3) / six_volume;
          v.lambda[0] = Number(1.) - v.lambda[1] - v.lambda[2] - v.lambda[3];
        }
      polygon.n_vertices = 3;

      // Which side of face i a point is on, decided by an orientation test
      // on the face's vertices in lexicographic order: every tetrahedron
      // sharing the face evaluates it bit for bit alike, so a point on a
      // shared face belongs to exactly one of them (for an exact zero: the
      // one whose opposite vertex has a positive orientation), and the
      // one-sided derivatives of neighbours add up to the derivative of the
      // total energy.
      const auto value_of = [&](const Point<3, Number> &x) {
        return Point<3>(value(x[0]), value(x[1]), value(x[2]));
      };
      const auto side = [&](const unsigned int i, const Point<3> &p) {
        std::array<Point<3>, 3> f;
        unsigned int            m = 0;
        for (unsigned int k = 0; k < 4; ++k)
          if (k != i)
            f[m++] = value_of(tet[k]);
        std::sort(f.begin(), f.end(), [](const Point<3> &a, const Point<3> &b) {
          return std::lexicographical_compare(&a[0],
                                              &a[0] + 3,
                                              &b[0],
                                              &b[0] + 3);
        });
        // values within rounding of zero are snapped to zero, so that a
        // polygon lying in the face plane gets one decision for all its
        // vertices instead of noise-driven alternating ones
        const Tensor<1, 3> e1 = f[1] - f[0], e2 = f[2] - f[0];
        const Tensor<1, 3> n = cross_product_3d(e1, e2);
        const double       s = n * (p - f[0]);
        const double       scale =
          n.norm() * (e1.norm() + e2.norm() + (p - f[0]).norm());
        return std::abs(s) <= 1e-12 * scale ? 0. : s;
      };

      for (unsigned int i = 0; i < 4 && polygon.n_vertices > 0; ++i)
        {
          const double inward = side(i, value_of(tet[i])) > 0. ? 1. : -1.;
          const auto   inside = [&](const PolygonVertex<Number> &v) {
            const double s = side(i, value_of(v.x)) * inward;
            return s > 0. || (s == 0. && inward > 0.);
          };
          clipped.n_vertices   = 0;
          const unsigned int n = polygon.n_vertices;
          for (unsigned int k = 0; k < n; ++k)
            {
              const PolygonVertex<Number> &p    = polygon.vertex[k];
              const PolygonVertex<Number> &q    = polygon.vertex[(k + 1) % n];
              const bool                   p_in = inside(p);
              const bool                   q_in = inside(q);
              // a convex polygon gains at most one vertex per plane; the
              // guard only protects against pathological rounding
              if (clipped.n_vertices + 2 > clipped.vertex.size())
                break;
              if (p_in)
                clipped.vertex[clipped.n_vertices++] = p;
              if (p_in != q_in)
                {
                  // crossing parameter from the barycentric coordinate,
                  // kept in [0, 1] where rounding disagrees with the side
                  const Number denominator = p.lambda[i] - q.lambda[i];
                  Number       t           = Number(0.);
                  if (value(denominator) != 0.)
                    t = p.lambda[i] / denominator;
                  if (value(t) < 0.)
                    t = Number(0.);
                  else if (value(t) > 1.)
                    t = Number(1.);
                  PolygonVertex<Number> &c =
                    clipped.vertex[clipped.n_vertices++];
                  c.x = p.x + t * (q.x - p.x);
                  for (unsigned int j = 0; j < 4; ++j)
                    c.lambda[j] = p.lambda[j] + t * (q.lambda[j] - p.lambda[j]);
                  c.lambda[i] = Number(0.);
                }
            }
          std::swap(polygon, clipped);
        }
      return polygon;
    }
  } // namespace Contact
} // namespace TissueContact
