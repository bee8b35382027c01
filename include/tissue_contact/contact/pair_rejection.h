#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <cmath>

namespace TissueContact
{
  using namespace dealii;

  namespace Contact
  {
    /**
     * What the rejection of a (triangle, tetrahedron) pair
     * (pair_rejected(), doc/theory/05-contact.md, sec. 2.2) needs of the
     * tetrahedron at some positions: its box and its barycentric frame,
     * @f$\lambda_i(p) = (p - v_0)\cdot m_i@f$ for i = 1, 2, 3 and
     * @f$\lambda_0 = 1 - \lambda_1 - \lambda_2 - \lambda_3@f$, with
     * @f$m_1 = (e_2\times e_3)/6V@f$, @f$m_2 = (e_3\times e_1)/6V@f$,
     * @f$m_3 = (e_1\times e_2)/6V@f$, @f$e_i = v_i - v_0@f$. A tetrahedron is
     * a candidate of every contact triangle near it, so its frame is made
     * once per evaluation and shared by them.
     */
    struct TetrahedronFrame
    {
      BoundingBox<3>              box;
      std::array<Point<3>, 4>     vertices;
      std::array<Tensor<1, 3>, 3> m;
      /** zero or non-finite volume: no frame, left to the clipping */
      bool degenerate = true;

      TetrahedronFrame() = default;

      /** The frame of @p tet; its barycentric part only if
       * @p with_barycentric (else make_barycentric() adds it). */
      explicit TetrahedronFrame(const std::array<Point<3>, 4> &tet,
                                const bool with_barycentric = true)
        : box(tet)
        , vertices(tet)
      {
        if (with_barycentric)
          make_barycentric();
      }

      /** The barycentric frame @f$m_i@f$ from the vertices, and whether
       * the tetrahedron is degenerate. */
      void
      make_barycentric()
      {
        const auto        &v  = vertices;
        const Tensor<1, 3> e1 = v[1] - v[0], e2 = v[2] - v[0], e3 = v[3] - v[0];
        const Tensor<1, 3> n1   = cross_product_3d(e2, e3),
                           n2   = cross_product_3d(e3, e1),
                           n3   = cross_product_3d(e1, e2);
        const double six_volume = e1 * n1;
        degenerate = !(std::abs(six_volume) > 0.) || !std::isfinite(six_volume);
        if (!degenerate)
          m = {{n1 / six_volume, n2 / six_volume, n3 / six_volume}};
      }
    };

    /** Ask the processor to fetch @p frame into its cache (all of its
     * cache lines) ahead of its use. */
    inline void
    prefetch(const TetrahedronFrame &frame)
    {
#if defined(__GNUC__)
      const char *p = reinterpret_cast<const char *>(&frame);
      for (unsigned int b = 0; b < sizeof(TetrahedronFrame); b += 64)
        __builtin_prefetch(p + b);
#else
      (void)frame;
#endif
    }

    /**
     * What the rejection needs of the triangle: its box and its plane's
     * normal @f$n = (t_1 - t_0)\times(t_2 - t_0)@f$ with its length and
     * the plane test's tolerance, @f$10^{-6}\sqrt{|n|}@f$ (10^{-6} of the
     * triangle's size). Made once per triangle and evaluation.
     */
    struct TriangleFrame
    {
      BoundingBox<3> box;
      Tensor<1, 3>   normal;
      double         n, limit;

      explicit TriangleFrame(const std::array<Point<3>, 3> &tri)
        : box(tri)
        , normal(cross_product_3d(tri[1] - tri[0], tri[2] - tri[0]))
        , n(normal.norm())
        , limit(1e-6 * std::sqrt(n))
      {}
    };

    /** The first test of pair_rejected(): the boxes are apart by more than
     * 1e-6 of the tetrahedron's size (the clipping could not find a point
     * within roundoff of both), for a pair without a shared vertex (boxes
     * with a common vertex always overlap). Reads only the frame's box. */
    inline bool
    boxes_apart(const std::array<unsigned char, 3> &shared,
                const TetrahedronFrame             &tet,
                const TriangleFrame                &tri_frame)
    {
      if (shared[0] < 4 || shared[1] < 4 || shared[2] < 4)
        return false;
      const auto &[lo, hi]         = tet.box.get_boundary_points();
      const auto &[tri_lo, tri_hi] = tri_frame.box.get_boundary_points();
      const double gap = 1e-6 * (hi[0] - lo[0] + hi[1] - lo[1] + hi[2] - lo[2]);
      for (unsigned int d = 0; d < 3; ++d)
        if (tri_lo[d] > hi[d] + gap || tri_hi[d] < lo[d] - gap)
          return true;
      return false;
    }

    /**
     * Whether a (triangle, tetrahedron) pair certainly has zero energy near
     * these positions, tested before the clipping (doc/theory/05-contact.md,
     * sec. 2.2); @p shared gives, for each triangle vertex, its index among
     * the tetrahedron's vertices (4 if none), @p tri the triangle's
     * vertices. The pair is rejected if
     * - the boxes are apart by more than 1e-6 of the tetrahedron's box
     *   size (tested only if no vertex is shared: boxes with a common
     *   vertex always overlap), or
     * - a face plane of the tetrahedron separates the triangle from it:
     *   every vertex of the triangle is outside it by more than 1e-6 in
     *   barycentric coordinates or is a vertex of the tetrahedron on that
     *   face (the triangle then touches the tetrahedron in a point or an
     *   edge of zero depth, as a surface triangle does its neighbours), or
     * - the triangle's plane separates them: every vertex of the
     *   tetrahedron lies beyond 1e-6 of the triangle's size on one side, or
     *   is a vertex of the triangle (on the plane).
     *
     * A degenerate tetrahedron or triangle is left to the clipping (not
     * rejected).
     */
    inline bool
    pair_rejected(const std::array<unsigned char, 3> &shared,
                  const TetrahedronFrame             &tet,
                  const TriangleFrame                &tri_frame,
                  const std::array<Point<3>, 3>      &tri)
    {
      if (boxes_apart(shared, tet, tri_frame))
        return true;
      if (tet.degenerate)
        return false;
      std::array<bool, 4> separates{{true, true, true, true}};
      for (unsigned int a = 0; a < 3; ++a)
        if (shared[a] < 4)
          separates[shared[a]] = false;
        else
          {
            const Tensor<1, 3>    r = tri[a] - tet.vertices[0];
            std::array<double, 4> lambda;
            lambda[1] = r * tet.m[0];
            lambda[2] = r * tet.m[1];
            lambda[3] = r * tet.m[2];
            lambda[0] = 1. - lambda[1] - lambda[2] - lambda[3];
            for (unsigned int i = 0; i < 4; ++i)
              separates[i] = separates[i] && lambda[i] < -1e-6;
          }
      if (separates[0] || separates[1] || separates[2] || separates[3])
        return true;
      if (!(tri_frame.n > 0.))
        return false;
      bool above = true, below = true;
      for (unsigned int j = 0; j < 4; ++j)
        {
          if (shared[0] == j || shared[1] == j || shared[2] == j)
            continue;
          const double d =
            tri_frame.normal * (tet.vertices[j] - tri[0]) / tri_frame.n;
          above = above && d > tri_frame.limit;
          below = below && d < -tri_frame.limit;
        }
      return above || below;
    }

    /**
     * pair_rejected() for a single pair whose tetrahedron has no frame
     * made: the box test first, the barycentric frame only if the boxes do
     * not already reject (as the tests were before the frames; a pattern
     * build meets its candidates in the tree walk's order, where no frame
     * can be fetched ahead).
     */
    inline bool
    pair_rejected(const std::array<unsigned char, 3> &shared,
                  const std::array<Point<3>, 4>      &tet,
                  const TriangleFrame                &tri_frame,
                  const std::array<Point<3>, 3>      &tri)
    {
      TetrahedronFrame frame(tet, false);
      if (boxes_apart(shared, frame, tri_frame))
        return true;
      frame.make_barycentric();
      return pair_rejected(shared, frame, tri_frame, tri);
    }
  } // namespace Contact
} // namespace TissueContact
