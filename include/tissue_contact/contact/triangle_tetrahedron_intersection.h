#pragma once

#include <deal.II/base/point.h>
#include <deal.II/differentiation/ad/ad_number_traits.h>

#include <algorithm>
#include <array>

namespace TissueContact
{
  namespace Contact
  {
    using namespace dealii;

    /** A vertex of the intersection polygon: its position, its
     * barycentric coordinates in the tetrahedron, and where it lies. A
     * vertex is the meeting point of two constraint lines in the triangle's
     * plane; constraint ids 0, 1, 2 are the triangle's edges (edge k from
     * vertex k to vertex k+1), 3 + i is face i of the tetrahedron (opposite
     * vertex i). @p edge_out is the constraint the polygon edge leaving the
     * vertex lies on. The exact kernel (penalty_kernel.h) differentiates
     * the vertex's closed form chosen by these labels. */
    template <typename Number>
    struct PolygonVertex
    {
      Point<3, Number>            x;
      std::array<Number, 4>       lambda;
      std::array<unsigned int, 2> on{{0, 0}};
      unsigned int                edge_out = 0;
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

      // two buffers, clipped from one into the other in turn
      IntersectionPolygon<Number>  buffers[2];
      IntersectionPolygon<Number> *from = &buffers[0], *to = &buffers[1];
      IntersectionPolygon<Number> &polygon = buffers[0];
      for (unsigned int k = 0; k < 3; ++k)
        {
          const Tensor<1, 3, Number> r = tri[k] - tet[0];
          PolygonVertex<Number>     &v = polygon.vertex[k];
          v.x                          = tri[k];
          v.lambda[1]                  = (r * n1) / six_volume;
          v.lambda[2]                  = (r * n2) / six_volume;
          v.lambda[3]                  = (r * n3) / six_volume;
          v.lambda[0] = Number(1.) - v.lambda[1] - v.lambda[2] - v.lambda[3];
          v.on        = {{(k + 2) % 3, k}};
          v.edge_out  = k;
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
      struct Face
      {
        Point<3>     f0;
        Tensor<1, 3> normal, e1, e2;
        // |normal|_1 (|e1|_1 + |e2|_1): bounds the scale below from above
        // without a square root; the Euclidean norms only near the plane
        double normal_l1, edge_l1;
        double normal_norm = -1., edge_norms = -1.;
      };
      std::array<Face, 4> faces;
      for (unsigned int i = 0; i < 4; ++i)
        {
          std::array<Point<3>, 3> f;
          unsigned int            m = 0;
          for (unsigned int k = 0; k < 4; ++k)
            if (k != i)
              f[m++] = value_of(tet[k]);
          // lexicographic order by three compare-exchanges (the face's
          // vertices are distinct; std::sort gives the same order)
          const auto less = [](const Point<3> &a, const Point<3> &b) {
            return a[0] < b[0] ||
                   (a[0] == b[0] &&
                    (a[1] < b[1] || (a[1] == b[1] && a[2] < b[2])));
          };
          if (less(f[1], f[0]))
            std::swap(f[0], f[1]);
          if (less(f[2], f[1]))
            std::swap(f[1], f[2]);
          if (less(f[1], f[0]))
            std::swap(f[0], f[1]);
          Face &face     = faces[i];
          face.f0        = f[0];
          face.e1        = f[1] - f[0];
          face.e2        = f[2] - f[0];
          face.normal    = cross_product_3d(face.e1, face.e2);
          face.normal_l1 = std::abs(face.normal[0]) + std::abs(face.normal[1]) +
                           std::abs(face.normal[2]);
          face.edge_l1 = std::abs(face.e1[0]) + std::abs(face.e1[1]) +
                         std::abs(face.e1[2]) + std::abs(face.e2[0]) +
                         std::abs(face.e2[1]) + std::abs(face.e2[2]);
        }
      // values within rounding of zero are snapped to zero, so that a
      // polygon lying in the face plane gets one decision for all its
      // vertices instead of noise-driven alternating ones
      const auto side = [&](const unsigned int i, const Point<3> &p) {
        Face              &f = faces[i];
        const Tensor<1, 3> r = p - f.f0;
        const double       s = f.normal * r;
        // |v| <= |v|_1: far from the plane (nearly always) the test needs
        // no square root, and decides as the exact one does
        const double r1 = std::abs(r[0]) + std::abs(r[1]) + std::abs(r[2]);
        if (std::abs(s) > 1e-12 * f.normal_l1 * (f.edge_l1 + r1))
          return s;
        if (f.normal_norm < 0.)
          {
            f.normal_norm = f.normal.norm();
            f.edge_norms  = f.e1.norm() + f.e2.norm();
          }
        if (std::abs(s) > 1e-12 * f.normal_norm * (f.edge_norms + r1))
          return s;
        const double scale = f.normal_norm * (f.edge_norms + r.norm());
        return std::abs(s) <= 1e-12 * scale ? 0. : s;
      };

      for (unsigned int i = 0; i < 4 && from->n_vertices > 0; ++i)
        {
          const double inward = side(i, value_of(tet[i])) > 0. ? 1. : -1.;
          const auto   inside = [&](const PolygonVertex<Number> &v) {
            const double s = side(i, value_of(v.x)) * inward;
            return s > 0. || (s == 0. && inward > 0.);
          };
          to->n_vertices        = 0;
          const unsigned int  n = from->n_vertices;
          std::array<bool, 9> is_inside;
          unsigned int        n_inside = 0;
          for (unsigned int k = 0; k < n; ++k)
            n_inside += (is_inside[k] = inside(from->vertex[k]));
          if (n_inside == n)
            continue;
          for (unsigned int k = 0; k < n; ++k)
            {
              const PolygonVertex<Number> &p    = from->vertex[k];
              const PolygonVertex<Number> &q    = from->vertex[(k + 1) % n];
              const bool                   p_in = is_inside[k];
              const bool                   q_in = is_inside[(k + 1) % n];
              // a convex polygon gains at most one vertex per plane; the
              // guard only protects against pathological rounding
              if (to->n_vertices + 2 > to->vertex.size())
                break;
              if (p_in)
                to->vertex[to->n_vertices++] = p;
              if (p_in != q_in)
                {
                  // crossing parameter from the barycentric coordinate,
                  // kept in [0, 1] where rounding disagrees with the side;
                  // the shift keeps the derivatives of lambda_p / (lambda_p
                  // - lambda_q), the one-sided derivatives of the case
                  // decided here (as the hand kernel's cut ratios do)
                  const Number denominator = p.lambda[i] - q.lambda[i];
                  Number       t           = Number(0.);
                  if (value(denominator) != 0.)
                    t = p.lambda[i] / denominator;
                  if (value(t) < 0.)
                    t -= value(t);
                  else if (value(t) > 1.)
                    t += 1. - value(t);
                  PolygonVertex<Number> &c = to->vertex[to->n_vertices++];
                  c.x                      = p.x + t * (q.x - p.x);
                  for (unsigned int j = 0; j < 4; ++j)
                    c.lambda[j] = p.lambda[j] + t * (q.lambda[j] - p.lambda[j]);
                  c.lambda[i] = Number(0.);
                  // the new vertex lies on the cut edge and on face i; the
                  // polygon continues along face i if it leaves the
                  // tetrahedron here, along the cut edge if it enters
                  c.on       = {{p.edge_out, 3 + i}};
                  c.edge_out = p_in ? 3 + i : p.edge_out;
                }
            }
          std::swap(from, to);
        }
      return *from;
    }
  } // namespace Contact
} // namespace TissueContact
