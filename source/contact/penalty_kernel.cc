#include <tissue_contact/base/cross_matrix.h>
#include <tissue_contact/base/multiversion.h>
#include <tissue_contact/contact/penalty_kernel.h>

#include <algorithm>

// Symbols follow doc/theory/05-contact.md, sec. 5.1.

// The kernel with the Hessian is compiled for AVX-512, AVX2 and the baseline
// x86-64, the same bits from each (base/multiversion.h; measured: sec. 5.1 of
// the document).

namespace TissueContact
{
  namespace Contact
  {
    namespace
    {
      constexpr unsigned int n = PairKernel::n_coordinates;
      using Vec                = std::array<double, n>;
      using Mat                = std::array<std::array<double, n>, n>;
      /** The 7 points of a pair: tetrahedron vertices 0..3, triangle
       * vertices 4..6; point P owns coordinates 3P, 3P+1, 3P+2. */
      using Points = std::array<Point<3>, 7>;

      /**
       * The orientation determinant
       * @f$O(p_0,p_1,p_2,p_3) = (p_1-p_0)\cdot((p_2-p_0)\times(p_3-p_0))@f$
       * of four of the points, with its gradient.
       */
      struct Orientation
      {
        std::array<unsigned int, 4> point;
        double                      value;
        std::array<Tensor<1, 3>, 4> gradient;
      };

      Orientation
      orientation(const Points &x, const std::array<unsigned int, 4> &P)
      {
        Orientation        o;
        const Tensor<1, 3> e1 = x[P[1]] - x[P[0]], e2 = x[P[2]] - x[P[0]],
                           e3 = x[P[3]] - x[P[0]];
        o.point               = P;
        o.gradient[1]         = cross_product_3d(e2, e3);
        o.gradient[2]         = cross_product_3d(e3, e1);
        o.gradient[3]         = cross_product_3d(e1, e2);
        o.gradient[0] = -(o.gradient[1] + o.gradient[2] + o.gradient[3]);
        o.value       = e1 * o.gradient[1];
        return o;
      }

      /** v += c grad O */
      void
      add_gradient(Vec &v, const Orientation &o, const double c)
      {
        for (unsigned int a = 0; a < 4; ++a)
          for (unsigned int d = 0; d < 3; ++d)
            v[3 * o.point[a] + d] += c * o.gradient[a][d];
      }

      /**
       * Half of c Hess O, added to @p M (the Hessian is M + M^T at the
       * end). O is affine in each point, so the diagonal blocks vanish;
       * block (a, b) is @f$[p_r - p_s]_\times@f$ for (a, b, r, s) an even
       * permutation of (0, 1, 2, 3), and block (b, a) its transpose: M gets
       * block (a, b) once.
       */
      void
      add_hessian(Mat &M, const Points &x, const Orientation &o, const double c)
      {
        static constexpr unsigned int even[6][4] = {{0, 1, 2, 3},
                                                    {0, 2, 3, 1},
                                                    {0, 3, 1, 2},
                                                    {1, 2, 0, 3},
                                                    {1, 3, 2, 0},
                                                    {2, 3, 0, 1}};
        for (const auto &perm : even)
          {
            const Tensor<1, 3> w =
              c * (x[o.point[perm[2]]] - x[o.point[perm[3]]]);
            const unsigned int i = 3 * o.point[perm[0]],
                               j = 3 * o.point[perm[1]];
            // [w]_x = [[0, -w2, w1], [w2, 0, -w0], [-w1, w0, 0]]
            M[i][j + 1] -= w[2];
            M[i][j + 2] += w[1];
            M[i + 1][j] += w[2];
            M[i + 1][j + 2] -= w[0];
            M[i + 2][j] -= w[1];
            M[i + 2][j + 1] += w[0];
          }
      }

      /** Half of c (a b^T + b a^T): M += c a b^T */
      void
      add_symmetric_outer(Mat &M, const Vec &a, const Vec &b, const double c)
      {
        for (unsigned int i = 0; i < n; ++i)
          {
            const double ai = c * a[i];
            if (ai != 0.)
              for (unsigned int j = 0; j < n; ++j)
                M[i][j] += ai * b[j];
          }
      }

      /** H = H + M + M^T, M in the half convention of the functions above */
      void
      add_symmetrized(Mat &H, const Mat &M)
      {
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = i; j < n; ++j)
            {
              const double v = M[i][j] + M[j][i];
              H[i][j] += v;
              if (j != i)
                H[j][i] += v;
            }
      }

      /** The nonzero entries of a 21-vector that is zero outside a few of
       * the 7 points: their coordinate indices. */
      struct Support
      {
        unsigned int                size = 0;
        std::array<unsigned int, n> i;

        /** the coordinates of the listed points (repeats allowed) */
        template <std::size_t N>
        explicit Support(const std::array<unsigned int, N> &points)
        {
          std::array<bool, 7> on{};
          for (const unsigned int P : points)
            on[P] = true;
          for (unsigned int P = 0; P < 7; ++P)
            if (on[P])
              for (unsigned int d = 0; d < 3; ++d)
                i[size++] = 3 * P + d;
        }
      };

      /** Half of c (a b^T + b a^T), a and b zero outside @p sa, @p sb:
       * M += c a b^T */
      void
      add_symmetric_outer(Mat           &M,
                          const Vec     &a,
                          const Support &sa,
                          const Vec     &b,
                          const Support &sb,
                          const double   c)
      {
        for (unsigned int p = 0; p < sa.size; ++p)
          {
            const unsigned int i  = sa.i[p];
            const double       ai = c * a[i];
            for (unsigned int q = 0; q < sb.size; ++q)
              M[i][sb.i[q]] += ai * b[sb.i[q]];
          }
      }

      /** The points an orientation depends on. */
      Support
      support(const Orientation &o)
      {
        return Support(o.point);
      }

      /** The depth field at a triangle vertex t: @f$G_t = N_t / V@f$ with
       * @f$N_t = \sum_j g_j D_{tj}@f$, @f$D_{tj}@f$ the orientation of the
       * tetrahedron with vertex j replaced by t, V its own orientation. */
      struct VertexDepth
      {
        std::array<Orientation, 4> D;
        double                     N, G;
        Vec                        grad_N, grad_G;
        /** the points N_t and G_t depend on: the tetrahedron's and t's */
        std::array<unsigned int, 5> points;
      };

      /** The depth field at triangle vertex @p t (point 4 + t). */
      VertexDepth
      vertex_depth(const Points                &x,
                   const Orientation           &V,
                   const std::array<double, 4> &g,
                   const unsigned int           t)
      {
        VertexDepth vd;
        vd.points = {{0, 1, 2, 3, 4 + t}};
        vd.N      = 0.;
        vd.grad_N.fill(0.);
        for (unsigned int j = 0; j < 4; ++j)
          {
            std::array<unsigned int, 4> P = {{0, 1, 2, 3}};
            P[j]                          = 4 + t;
            vd.D[j]                       = orientation(x, P);
            vd.N += g[j] * vd.D[j].value;
            add_gradient(vd.grad_N, vd.D[j], g[j]);
          }
        vd.G = vd.N / V.value;
        for (unsigned int i = 0; i < n; ++i)
          vd.grad_G[i] = vd.grad_N[i] / V.value;
        add_gradient(vd.grad_G, V, -vd.N / (V.value * V.value));
        return vd;
      }

      /** Half of omega Hess G_t, G_t = N_t / V (quotient rule), added to
       * @p M. */
      void
      add_depth_hessian(Mat                         &M,
                        const Points                &x,
                        const Orientation           &V,
                        const VertexDepth           &vd,
                        const std::array<double, 4> &g,
                        const double                 omega)
      {
        const double Vv = V.value;
        for (unsigned int j = 0; j < 4; ++j)
          add_hessian(M, x, vd.D[j], omega * g[j] / Vv);
        add_hessian(M, x, V, -omega * vd.N / (Vv * Vv));
        Vec gV{};
        add_gradient(gV, V, 1.);
        const Support sV = support(V), sN(vd.points);
        add_symmetric_outer(M, vd.grad_N, sN, gV, sV, -omega / (Vv * Vv));
        add_symmetric_outer(M, gV, sV, gV, sV, omega * vd.N / (Vv * Vv * Vv));
      }


      /** Twice the triangle's area, @f$N = |N_T|@f$,
       * @f$N_T = (t_1 - t_0)\times(t_2 - t_0)@f$, its unit normal and, on
       * request, its gradient and Hessian in the triangle's 9 coordinates
       * (points 4, 5, 6): @f$\partial N/\partial t_X = M_X^T\nu@f$ and
       * @f$M_X^T(I - \nu\nu^T)M_Y/N@f$ plus the bilinear part of
       * @f$N_T@f$ weighted by @f$\nu@f$, @f$M_X = \partial N_T/\partial
       * t_X@f$. */
      struct TriangleArea
      {
        double                                     N = 0.;
        Tensor<1, 3>                               nu;
        std::array<Tensor<1, 3>, 3>                gradient;
        std::array<std::array<Tensor<2, 3>, 3>, 3> hessian;

        explicit TriangleArea(const std::array<Point<3>, 3> &tri)
        {
          const Tensor<1, 3> NT =
            cross_product_3d(tri[1] - tri[0], tri[2] - tri[0]);
          N  = NT.norm();
          nu = NT / N;
        }

        void
        derivatives(const std::array<Point<3>, 3> &tri, const bool hessian_too)
        {
          // M_X = [m_X]_x with the edge vectors m_X = t_{X+2} - t_{X+1}
          const std::array<Tensor<1, 3>, 3> m = {
            {tri[2] - tri[1], tri[0] - tri[2], tri[1] - tri[0]}};
          std::array<Tensor<1, 3>, 3> nm; // M_X^T nu = nu x m_X
          for (unsigned int X = 0; X < 3; ++X)
            gradient[X] = nm[X] = cross_product_3d(nu, m[X]);
          if (!hessian_too)
            return;
          // M_X^T (I - nu nu^T) M_Y / N = ((m_X . m_Y) I - m_Y m_X^T
          // - (nu x m_X)(nu x m_Y)^T) / N, and the bilinear part
          const Tensor<2, 3> Bn = -cross_matrix(nu);
          for (unsigned int X = 0; X < 3; ++X)
            for (unsigned int Y = 0; Y < 3; ++Y)
              {
                Tensor<2, 3> &h = hessian[X][Y];
                h = -(outer_product(m[Y], m[X]) + outer_product(nm[X], nm[Y]));
                const double mm = m[X] * m[Y];
                for (unsigned int d = 0; d < 3; ++d)
                  h[d][d] += mm;
                h /= N;
                if ((Y + 3 - X) % 3 == 1)
                  h += Bn;
                else if ((X + 3 - Y) % 3 == 1)
                  h -= Bn;
              }
        }
      };


      /** The tetrahedron's barycentric functions
       * @f$\lambda_j(y) = a_j\cdot y + b_j@f$ at the triangle's vertices:
       * @f$\Lambda_{jt} = \lambda_j(t_t)@f$, and the depth field there,
       * @f$G_t = \sum_j g_j\Lambda_{jt}@f$ (doc/theory/05-contact.md, sec.
       * 5.1). */
      struct Barycentric
      {
        std::array<Tensor<1, 3>, 4>          a;
        std::array<std::array<double, 3>, 4> L;
        std::array<double, 3>                G;
        /** the depth field's gradient, @f$\eta = \sum_j g_j a_j@f$ */
        Tensor<1, 3> eta;

        Barycentric(const Points &x, const std::array<double, 4> &g)
        {
          const Tensor<1, 3> e1 = x[1] - x[0], e2 = x[2] - x[0],
                             e3 = x[3] - x[0];
          const Tensor<1, 3> n1 = cross_product_3d(e2, e3);
          const double       V  = e1 * n1;
          a[1]                  = n1 / V;
          a[2]                  = cross_product_3d(e3, e1) / V;
          a[3]                  = cross_product_3d(e1, e2) / V;
          a[0]                  = -(a[1] + a[2] + a[3]);
          eta = g[0] * a[0] + g[1] * a[1] + g[2] * a[2] + g[3] * a[3];
          for (unsigned int t = 0; t < 3; ++t)
            {
              const Tensor<1, 3> r = x[4 + t] - x[0];
              for (unsigned int j = 1; j < 4; ++j)
                L[j][t] = r * a[j];
              // lambda_0 measured from v_1, on its face: no cancellation
              L[0][t] = (x[4 + t] - x[1]) * a[0];
              G[t]    = g[0] * L[0][t] + g[1] * L[1][t] + g[2] * L[2][t] +
                     g[3] * L[3][t];
            }
        }
      };


      /**
       * A polygon vertex in the triangle's barycentric coordinates
       * @f$\zeta@f$, from its clipping labels: a triangle vertex
       * (@f$\zeta = e_t@f$, constant), a triangle edge @f$t_at_b@f$ cut by
       * face i (@f$\zeta = (1-s)e_a + s e_b@f$,
       * @f$s = \Lambda_{ia}/(\Lambda_{ia} - \Lambda_{ib})@f$), or the
       * tetrahedron edge on faces i and j cut by the triangle's plane
       * (@f$\zeta = \kappa/\sigma@f$, @f$\kappa = \Lambda_i\times\Lambda_j@f$
       * of the rows i, j of @f$\Lambda@f$, @f$\sigma = \mathbf
       * 1\cdot\kappa@f$). Its parameters (none, s, or the three components of
       * @f$\zeta@f$) start
       * at index @p p.
       */
      struct ZetaVertex
      {
        enum Kind
        {
          fixed,
          edge_cut,
          plane_cut
        } kind;
        Tensor<1, 3> zeta;
        unsigned int p, n_p;
        // edge_cut: ta, tb, face i and the derivatives of s in
        // A = Lambda_{i ta}, B = Lambda_{i tb}
        unsigned int i, j, ta, tb;
        double       s_A, s_B, s_AA, s_AB, s_BB;
        // plane_cut: faces i and j, sigma and the derivatives of sigma and
        // zeta in (u_0, u_1, u_2, w_0, w_1, w_2), u = Lambda_i, w = Lambda_j
        double                               sigma;
        std::array<double, 6>                dsigma;
        std::array<std::array<double, 3>, 6> dzeta;
      };

      /** @f$\zeta@f$ of a point of the triangle's plane (area ratios) */
      Tensor<1, 3>
      zeta_of(const Points &x, const TriangleArea &area, const Point<3> &y)
      {
        Tensor<1, 3> z;
        for (unsigned int t = 0; t < 3; ++t)
          z[t] =
            cross_product_3d(x[4 + (t + 1) % 3] - y, x[4 + (t + 2) % 3] - y) *
            area.nu / area.N;
        return z;
      }

      /** Stage 1: the polygon's vertices in closed form from their labels;
       * returns the number of parameters (the last three, G, included). */
      unsigned int
      polygon_vertices(const IntersectionPolygon<double> &polygon,
                       const Points                      &x,
                       const Barycentric                 &bary,
                       const TriangleArea                &area,
                       std::array<ZetaVertex, 9>         &form)
      {
        const auto        &L = bary.L;
        unsigned int       p = 0;
        const unsigned int m = polygon.n_vertices;
        for (unsigned int k = 0; k < m; ++k)
          {
            ZetaVertex  &v  = form[k];
            unsigned int c1 = polygon.vertex[k].on[0],
                         c2 = polygon.vertex[k].on[1];
            if (c1 > c2)
              std::swap(c1, c2);
            v.kind = ZetaVertex::fixed;
            v.zeta = Tensor<1, 3>();
            if (c2 < 3)
              // two triangle edges: a triangle vertex
              v.zeta[(c2 == c1 + 1) ? c2 : 0] = 1.;
            else if (c1 < 3)
              {
                // triangle edge c1 cut by face i
                v.ta           = c1;
                v.tb           = (c1 + 1) % 3;
                v.i            = c2 - 3;
                const double A = L[v.i][v.ta], B = L[v.i][v.tb], d = A - B;
                double       s = 0.;
                if (d != 0.)
                  {
                    // rounding may disagree with the side decision: the cut
                    // then sits at the end point, as in intersect(), but s
                    // keeps the derivatives of A / (A - B), the one-sided
                    // derivatives of the clipping case intersect() chose
                    s      = std::clamp(A / d, 0., 1.);
                    v.kind = ZetaVertex::edge_cut;
                    v.s_A  = -B / (d * d);
                    v.s_B  = A / (d * d);
                    v.s_AA = 2. * B / (d * d * d);
                    v.s_BB = 2. * A / (d * d * d);
                    v.s_AB = -(A + B) / (d * d * d);
                  }
                v.zeta[v.ta] = 1. - s;
                v.zeta[v.tb] = s;
              }
            else
              {
                // faces i and j: the tetrahedron edge p q between them cut
                // by the triangle's plane
                v.i = c1 - 3;
                v.j = c2 - 3;
                const Tensor<1, 3> u({L[v.i][0], L[v.i][1], L[v.i][2]}),
                  w({L[v.j][0], L[v.j][1], L[v.j][2]});
                const Tensor<1, 3> kappa = cross_product_3d(u, w);
                v.sigma                  = kappa[0] + kappa[1] + kappa[2];
                if (v.sigma != 0.)
                  {
                    v.kind = ZetaVertex::plane_cut;
                    v.zeta = kappa / v.sigma;
                    // where rounding puts the cut beyond the edge's end
                    // (lambda of an end point below zero), its value is the
                    // clipping's point, its derivatives those of kappa / sigma
                    unsigned int q = 4;
                    for (unsigned int r = 0; r < 4; ++r)
                      if (r != v.i && r != v.j)
                        q = r;
                    const double lq = (L[q][0] * kappa[0] + L[q][1] * kappa[1] +
                                       L[q][2] * kappa[2]) /
                                      v.sigma;
                    if (lq < 0. || lq > 1.)
                      v.zeta = zeta_of(x, area, polygon.vertex[k].x);
                    for (unsigned int t = 0; t < 3; ++t)
                      {
                        Tensor<1, 3> e;
                        e[t]                   = 1.;
                        const Tensor<1, 3> dku = cross_product_3d(e, w),
                                           dkw = cross_product_3d(u, e);
                        v.dsigma[t]            = dku[0] + dku[1] + dku[2];
                        v.dsigma[3 + t]        = dkw[0] + dkw[1] + dkw[2];
                        for (unsigned int d = 0; d < 3; ++d)
                          {
                            v.dzeta[t][d] =
                              (dku[d] - v.dsigma[t] * v.zeta[d]) / v.sigma;
                            v.dzeta[3 + t][d] =
                              (dkw[d] - v.dsigma[3 + t] * v.zeta[d]) / v.sigma;
                          }
                      }
                  }
                else
                  // the edge in the plane: the clipping's point, held fixed
                  v.zeta = zeta_of(x, area, polygon.vertex[k].x);
              }
            v.p   = p;
            v.n_p = v.kind == ZetaVertex::edge_cut  ? 1 :
                    v.kind == ZetaVertex::plane_cut ? 3 :
                                                      0;
            p += v.n_p;
          }
        return p + 3;
      }


      /** At most 3 parameters per polygon vertex (9 slots, sec. 3), then G */
      constexpr unsigned int max_parameters = 3 * 9 + 3;

      /** The fan integral and its derivatives in the parameters: the
       * vertices' s or zeta, then G (3). */
      struct FanIntegral
      {
        unsigned int                                                   n_p = 0;
        double                                                         Phi = 0.;
        std::array<double, max_parameters>                             g{};
        std::array<std::array<double, max_parameters>, max_parameters> H;
      };

      /** @f$B_k^T y@f$: the projection of a zeta-space vector on the
       * parameter basis B_k of a vertex, @f$e_{t_b} - e_{t_a}@f$ for an edge
       * cut, the identity for a plane cut; into @p out[0..n_p). */
      inline void
      project(const ZetaVertex &v, const Tensor<1, 3> &y, double *out)
      {
        if (v.kind == ZetaVertex::edge_cut)
          out[0] = y[v.tb] - y[v.ta];
        else
          for (unsigned int c = 0; c < 3; ++c)
            out[c] = y[c];
      }

      /** @f$B_k^T M@f$: the projection of each column of a zeta-space
       * matrix, into @p out[0..n_p)[0..3). */
      inline void
      project_rows(const ZetaVertex &v, const Tensor<2, 3> &M, double out[3][3])
      {
        for (unsigned int e = 0; e < 3; ++e)
          {
            double column[3];
            project(v, Tensor<1, 3>({M[0][e], M[1][e], M[2][e]}), column);
            for (unsigned int a = 0; a < v.n_p; ++a)
              out[a][e] = column[a];
          }
      }

      /** @f$B_r^T M B_s@f$ added to the parameters' Hessian at (p_r, p_s)
       * and, for two vertices, its transpose at (p_s, p_r). */
      inline void
      add_block(
        std::array<std::array<double, max_parameters>, max_parameters> &H,
        const ZetaVertex                                               &vr,
        const ZetaVertex                                               &vs,
        const Tensor<2, 3>                                             &M,
        const bool                                                      mirror)
      {
        double rows[3][3];
        project_rows(vr, M, rows);
        for (unsigned int a = 0; a < vr.n_p; ++a)
          {
            double cols[3];
            project(vs,
                    Tensor<1, 3>({rows[a][0], rows[a][1], rows[a][2]}),
                    cols);
            for (unsigned int c = 0; c < vs.n_p; ++c)
              {
                H[vr.p + a][vs.p + c] += cols[c];
                if (mirror)
                  H[vs.p + c][vr.p + a] += cols[c];
              }
          }
      }

      /**
       * Stage 2: @f$\Phi = \sum_k d_k Q_k@f$ over the fan triangles
       * @f$(\zeta_0, \zeta_k, \zeta_{k+1})@f$, @f$d_k = \det[\zeta_0,
       * \zeta_k, \zeta_{k+1}]@f$, @f$Q_k = \tfrac12 h^TEh@f$ with
       * @f$h = (G\cdot\zeta_0, G\cdot\zeta_k, G\cdot\zeta_{k+1})@f$, and its
       * gradient and Hessian in the parameters: the derivatives in the rows
       * @f$z_r@f$ of the fan triangle (sec. 5.1), 3 by 3 blocks in zeta,
       * projected on each row's parameter basis.
       */
      void
      fan_integral(const std::array<ZetaVertex, 9> &form,
                   const unsigned int               m,
                   const Barycentric               &bary,
                   const bool                       with_hessian,
                   FanIntegral                     &fan)
      {
        const unsigned int iG = fan.n_p - 3;
        const Tensor<1, 3> G({bary.G[0], bary.G[1], bary.G[2]});
        const Tensor<2, 3> GG = outer_product(G, G);
        if (with_hessian)
          for (unsigned int a = 0; a < fan.n_p; ++a)
            std::fill(fan.H[a].begin(), fan.H[a].begin() + fan.n_p, 0.);
        for (unsigned int k = 1; k + 1 < m; ++k)
          {
            const std::array<const ZetaVertex *, 3> v = {
              {&form[0], &form[k], &form[k + 1]}};
            const std::array<Tensor<1, 3>, 3> z = {
              {v[0]->zeta, v[1]->zeta, v[2]->zeta}};
            // d_r = dd/dz_r: the cross product of the other two rows
            const std::array<Tensor<1, 3>, 3> dd = {
              {cross_product_3d(z[1], z[2]),
               cross_product_3d(z[2], z[0]),
               cross_product_3d(z[0], z[1])}};
            const double                d  = z[0] * dd[0];
            const std::array<double, 3> h  = {{G * z[0], G * z[1], G * z[2]}};
            const double                hs = h[0] + h[1] + h[2];
            const std::array<double, 3> Eh = {
              {hs + h[0], hs + h[1], hs + h[2]}};
            const double Q = 0.5 * (Eh[0] * h[0] + Eh[1] * h[1] + Eh[2] * h[2]);
            fan.Phi += d * Q;
            // dQ/dG = Z^T E h
            const Tensor<1, 3> mG = Eh[0] * z[0] + Eh[1] * z[1] + Eh[2] * z[2];
            // dPhi/dz_r = Q d_r + d Eh_r G
            for (unsigned int r = 0; r < 3; ++r)
              if (v[r]->n_p > 0)
                {
                  double g[3];
                  project(*v[r], Q * dd[r] + (d * Eh[r]) * G, g);
                  for (unsigned int a = 0; a < v[r]->n_p; ++a)
                    fan.g[v[r]->p + a] += g[a];
                }
            for (unsigned int t = 0; t < 3; ++t)
              fan.g[iG + t] += d * mG[t];
            if (!with_hessian)
              continue;
            // (E Z)_r = z_r + sum of the rows
            const Tensor<1, 3> zs = z[0] + z[1] + z[2];
            for (unsigned int r = 0; r < 3; ++r)
              {
                if (v[r]->n_p == 0)
                  continue;
                // rows (r, s): Eh_s d_r G^T + Eh_r G d_s^T + d E_rs G G^T
                // + Q d2 det / dz_r dz_s, the last -[z_t]_x for s = r + 1
                // and its transpose for s = r + 2
                for (unsigned int s = r; s < 3; ++s)
                  {
                    if (v[s]->n_p == 0)
                      continue;
                    Tensor<2, 3> M = Eh[s] * outer_product(dd[r], G) +
                                     Eh[r] * outer_product(G, dd[s]) +
                                     (d * (r == s ? 2. : 1.)) * GG;
                    if (s == (r + 1) % 3)
                      M -= Q * cross_matrix(z[3 - r - s]);
                    else if (s != r)
                      M += Q * cross_matrix(z[3 - r - s]);
                    add_block(fan.H, *v[r], *v[s], M, s != r);
                  }
                // (r, G): d_r mG^T + d G (z_r + zs)^T + d Eh_r I
                Tensor<2, 3> C =
                  outer_product(dd[r], mG) + d * outer_product(G, z[r] + zs);
                for (unsigned int e = 0; e < 3; ++e)
                  C[e][e] += d * Eh[r];
                double BC[3][3];
                project_rows(*v[r], C, BC);
                for (unsigned int a = 0; a < v[r]->n_p; ++a)
                  for (unsigned int e = 0; e < 3; ++e)
                    {
                      fan.H[v[r]->p + a][iG + e] += BC[a][e];
                      fan.H[iG + e][v[r]->p + a] += BC[a][e];
                    }
              }
            // (G, G): d Z^T E Z = d (sum_r z_r z_r^T + zs zs^T)
            const Tensor<2, 3> MG =
              d * (outer_product(z[0], z[0]) + outer_product(z[1], z[1]) +
                   outer_product(z[2], z[2]) + outer_product(zs, zs));
            for (unsigned int a = 0; a < 3; ++a)
              for (unsigned int b = 0; b < 3; ++b)
                fan.H[iG + a][iG + b] += MG[a][b];
          }
      }


      /** The derivatives of Phi in Lambda (index 3 j + t), split: the
       * polygon vertices' part in full, G's part (@f$G_t = \sum_j
       * g_j\Lambda_{jt}@f$) by its derivatives in G, which
       * to_coordinates() chains through @f$\eta@f$. */
      struct LambdaDerivatives
      {
        /** dPhi/dLambda through the vertices; dPhi/dG */
        std::array<double, 12> d;
        Tensor<1, 3>           dG;
        /** the rows j of Lambda the vertices depend on (bit j) */
        unsigned int faces = 0;
        /** the vertices' Hessian in Lambda, rows and columns of @p faces */
        std::array<std::array<double, 12>, 12> H;
        /** the mixed second derivatives in (Lambda, G) through the
         * vertices, @f$X_{\alpha u} = \partial^2\Phi/\partial\Lambda_\alpha
         * \partial G_u@f$ (rows of @p faces), and those in G */
        std::array<Tensor<1, 3>, 12> X;
        Tensor<2, 3>                 HG;
      };

      /** A polygon vertex's parameters as functions of the (at most six)
       * entries of Lambda they depend on: @f$J_{al} = \partial
       * p_a/\partial\Lambda_{\alpha_l}@f$. */
      struct VertexJacobian
      {
        /** the vertex's place k in the polygon, its parameters' first
         * index p and count n_p, its Lambda entries' count n_l */
        unsigned int                         k, p, n_p, n_l;
        std::array<unsigned int, 6>          alpha;
        std::array<std::array<double, 6>, 3> J;
      };

      /** (vertex b, G): @f$X \mathrel{+}= J_b^T H_{bG}@f$, with the
       * vertex's numbers of parameters and Lambda entries fixed */
      template <unsigned int NP, unsigned int NL>
      inline void
      add_vertex_G(const FanIntegral    &fan,
                   const VertexJacobian &wb,
                   const unsigned int    iG,
                   LambdaDerivatives    &ld)
      {
        for (unsigned int l = 0; l < NL; ++l)
          for (unsigned int u = 0; u < 3; ++u)
            {
              double x = 0.;
              for (unsigned int a = 0; a < NP; ++a)
                x += wb.J[a][l] * fan.H[wb.p + a][iG + u];
              ld.X[wb.alpha[l]][u] += x;
            }
      }

      /** (vertex b, vertex c): @f$J_b^T H_{bc} J_c@f$ and, for two
       * vertices, its mirror */
      template <unsigned int NPb,
                unsigned int NLb,
                unsigned int NPc,
                unsigned int NLc>
      inline void
      add_vertex_pair(const FanIntegral    &fan,
                      const VertexJacobian &wb,
                      const VertexJacobian &wc,
                      const bool            mirror,
                      LambdaDerivatives    &ld)
      {
        double HJ[NPb][NLc];
        for (unsigned int a = 0; a < NPb; ++a)
          for (unsigned int l = 0; l < NLc; ++l)
            {
              double x = 0.;
              for (unsigned int e = 0; e < NPc; ++e)
                x += fan.H[wb.p + a][wc.p + e] * wc.J[e][l];
              HJ[a][l] = x;
            }
        for (unsigned int k = 0; k < NLb; ++k)
          for (unsigned int l = 0; l < NLc; ++l)
            {
              double y = 0.;
              for (unsigned int a = 0; a < NPb; ++a)
                y += wb.J[a][k] * HJ[a][l];
              ld.H[wb.alpha[k]][wc.alpha[l]] += y;
              if (mirror)
                ld.H[wc.alpha[l]][wb.alpha[k]] += y;
            }
      }

      /**
       * Stage 3: the gradient and Hessian of Phi in Lambda by the chain rule
       * through the vertices' parameters, block by block (each vertex
       * depends on one or two rows of Lambda), with the second derivatives
       * of s (edge cuts) and of zeta = kappa / sigma (plane cuts).
       */
      void
      chain_to_lambda(const std::array<ZetaVertex, 9> &form,
                      const unsigned int               m,
                      const FanIntegral               &fan,
                      const bool                       with_hessian,
                      LambdaDerivatives               &ld)
      {
        const unsigned int            iG = fan.n_p - 3;
        std::array<VertexJacobian, 9> vj;
        unsigned int                  n_v = 0;
        ld.faces                          = 0;
        for (unsigned int k = 0; k < m; ++k)
          {
            const ZetaVertex &v = form[k];
            if (v.kind == ZetaVertex::fixed)
              continue;
            VertexJacobian &w = vj[n_v++];
            w.k               = k;
            w.p               = v.p;
            w.n_p             = v.n_p;
            if (v.kind == ZetaVertex::edge_cut)
              {
                w.n_l      = 2;
                w.alpha[0] = 3 * v.i + v.ta;
                w.alpha[1] = 3 * v.i + v.tb;
                w.J[0][0]  = v.s_A;
                w.J[0][1]  = v.s_B;
                ld.faces |= 1u << v.i;
              }
            else
              {
                w.n_l = 6;
                for (unsigned int t = 0; t < 3; ++t)
                  {
                    w.alpha[t]     = 3 * v.i + t;
                    w.alpha[3 + t] = 3 * v.j + t;
                    for (unsigned int c = 0; c < 3; ++c)
                      {
                        w.J[c][t]     = v.dzeta[t][c];
                        w.J[c][3 + t] = v.dzeta[3 + t][c];
                      }
                  }
                ld.faces |= (1u << v.i) | (1u << v.j);
              }
          }
        ld.d.fill(0.);
        for (unsigned int b = 0; b < n_v; ++b)
          for (unsigned int a = 0; a < vj[b].n_p; ++a)
            for (unsigned int l = 0; l < vj[b].n_l; ++l)
              ld.d[vj[b].alpha[l]] += fan.g[vj[b].p + a] * vj[b].J[a][l];
        for (unsigned int t = 0; t < 3; ++t)
          ld.dG[t] = fan.g[iG + t];
        if (!with_hessian)
          return;
        for (unsigned int j = 0; j < 4; ++j)
          if (ld.faces & (1u << j))
            for (unsigned int t = 0; t < 3; ++t)
              {
                ld.H[3 * j + t].fill(0.);
                ld.X[3 * j + t] = Tensor<1, 3>();
              }
        for (unsigned int u = 0; u < 3; ++u)
          for (unsigned int e = 0; e < 3; ++e)
            ld.HG[u][e] = fan.H[iG + u][iG + e];
        for (unsigned int b = 0; b < n_v; ++b)
          {
            const VertexJacobian &wb = vj[b];
            if (wb.n_p == 1)
              add_vertex_G<1, 2>(fan, wb, iG, ld);
            else
              add_vertex_G<3, 6>(fan, wb, iG, ld);
            for (unsigned int cc = b; cc < n_v; ++cc)
              {
                const VertexJacobian &wc = vj[cc];
                // the fan triangles (0, k, k + 1) couple vertex 0 with all
                // and vertex k with k + 1 only: the other blocks are zero
                if (wb.k != 0 && wc.k != wb.k && wc.k != wb.k + 1)
                  continue;
                if (wb.n_p == 1 && wc.n_p == 1)
                  add_vertex_pair<1, 2, 1, 2>(fan, wb, wc, cc != b, ld);
                else if (wb.n_p == 1)
                  add_vertex_pair<1, 2, 3, 6>(fan, wb, wc, true, ld);
                else if (wc.n_p == 1)
                  add_vertex_pair<3, 6, 1, 2>(fan, wb, wc, true, ld);
                else
                  add_vertex_pair<3, 6, 3, 6>(fan, wb, wc, cc != b, ld);
              }
          }
        // the parameters' second derivatives, weighted by dPhi/dparameter
        for (unsigned int k = 0; k < m; ++k)
          {
            const ZetaVertex &v = form[k];
            if (v.kind == ZetaVertex::edge_cut)
              {
                const double       gs = fan.g[v.p];
                const unsigned int A = 3 * v.i + v.ta, B = 3 * v.i + v.tb;
                ld.H[A][A] += gs * v.s_AA;
                ld.H[A][B] += gs * v.s_AB;
                ld.H[B][A] += gs * v.s_AB;
                ld.H[B][B] += gs * v.s_BB;
              }
            else if (v.kind == ZetaVertex::plane_cut)
              {
                // phi = gz . zeta = gz . kappa / sigma, kappa = u x w: with
                // beta = gz - phi 1, d phi = beta . dkappa / sigma and
                // d2 phi = (beta . d2kappa - dphi dsigma^T - dsigma dphi^T) /
                // sigma, d2kappa/du_t dw_s = e_t x e_s
                const Tensor<1, 3> gz(
                  {fan.g[v.p], fan.g[v.p + 1], fan.g[v.p + 2]});
                const double       phi  = gz * v.zeta;
                const Tensor<1, 3> beta = gz - phi * Tensor<1, 3>({1., 1., 1.});
                std::array<double, 6> dphi;
                for (unsigned int a = 0; a < 6; ++a)
                  dphi[a] = gz[0] * v.dzeta[a][0] + gz[1] * v.dzeta[a][1] +
                            gz[2] * v.dzeta[a][2];
                const double inv = 1. / v.sigma;
                // (u_t, w_s): beta . (e_t x e_s) = beta_r for (t, s, r)
                // cyclic, -beta_r anticyclic
                double cross[3][3] = {{0., beta[2], -beta[1]},
                                      {-beta[2], 0., beta[0]},
                                      {beta[1], -beta[0], 0.}};
                for (unsigned int a = 0; a < 6; ++a)
                  {
                    const unsigned int ia =
                      a < 3 ? 3 * v.i + a : 3 * v.j + a - 3;
                    for (unsigned int b = 0; b < 6; ++b)
                      {
                        const unsigned int ib =
                          b < 3 ? 3 * v.i + b : 3 * v.j + b - 3;
                        double h =
                          -(dphi[a] * v.dsigma[b] + v.dsigma[a] * dphi[b]);
                        if (a < 3 && b >= 3)
                          h += cross[a][b - 3];
                        else if (a >= 3 && b < 3)
                          h += cross[b][a - 3];
                        ld.H[ia][ib] += h * inv;
                      }
                  }
              }
          }
      }


      /**
       * Stage 4: from Lambda to the 21 coordinates. With
       * @f$\delta y_t = \delta t_t - \sum_i\Lambda_{it}\delta v_i@f$,
       * @f$\delta\Lambda_{jt} = a_j\cdot\delta y_t@f$ and
       * @f$\delta^2\Lambda_{jt} = -2\sum_k(a_j\cdot\delta v_k)(a_k\cdot\delta
       * y_t)@f$:
       * @f$q_t = \sum_j\Phi_{jt}a_j@f$, @f$K_{tu} = \sum_{jk}\Phi_{jt,ku}
       * a_j a_k^T@f$, @f$r_i = \sum_t\Lambda_{it}q_t@f$,
       * @f$R_{iu} = \sum_t\Lambda_{it}K_{tu}@f$; the gradient of Phi is
       * @f$q_t@f$ at t_t and @f$-r_i@f$ at v_i, its Hessian has the blocks
       * @f$K_{tu}@f$, @f$-R_{iu} - q_u a_i^T@f$ (v_i, t_u) and
       * @f$\sum_u\Lambda_{iu}R_{ku} + r_i a_k^T + a_i r_k^T@f$ (v_k, v_i).
       * G's part enters through @f$\partial G_t/\partial\Lambda_{jt} =
       * g_j@f$: @f$\Phi_{jt}@f$ gains @f$g_j\Phi_{G_t}@f$, so @f$q_t@f$
       * gains @f$\Phi_{G_t}\eta@f$ and @f$K_{tu}@f$ gains
       * @f$w_{tu}\eta^T + \eta w_{ut}^T + \Phi_{G_tG_u}\eta\eta^T@f$,
       * @f$w_{tu} = \sum_j X_{jt,u}a_j@f$. Then @f$W = cN\Phi@f$.
       */
      void
      to_coordinates(const Barycentric       &bary,
                     const TriangleArea      &area,
                     const double             Phi,
                     const LambdaDerivatives &ld,
                     const double             c,
                     const bool               with_hessian,
                     PairKernel              &result)
      {
        const auto                 &a   = bary.a;
        const auto                 &L   = bary.L;
        const Tensor<1, 3>         &eta = bary.eta;
        std::array<Tensor<1, 3>, 3> q;
        for (unsigned int t = 0; t < 3; ++t)
          q[t] = ld.d[t] * a[0] + ld.d[3 + t] * a[1] + ld.d[6 + t] * a[2] +
                 ld.d[9 + t] * a[3] + ld.dG[t] * eta;
        std::array<Tensor<1, 3>, 4> r;
        for (unsigned int i = 0; i < 4; ++i)
          r[i] = L[i][0] * q[0] + L[i][1] * q[1] + L[i][2] * q[2];
        // the gradient of W = c N Phi
        const double cN = c * area.N, cPhi = c * Phi;
        for (unsigned int i = 0; i < 4; ++i)
          for (unsigned int d = 0; d < 3; ++d)
            result.gradient[3 * i + d] = -cN * r[i][d];
        for (unsigned int t = 0; t < 3; ++t)
          for (unsigned int d = 0; d < 3; ++d)
            result.gradient[3 * (4 + t) + d] =
              cN * q[t][d] + cPhi * area.gradient[t][d];
        if (!with_hessian)
          return;

        // the rows of Lambda the vertices depend on
        std::array<unsigned int, 4> face;
        unsigned int                n_f = 0;
        for (unsigned int j = 0; j < 4; ++j)
          if (ld.faces & (1u << j))
            face[n_f++] = j;
        // w_tu = sum_j X_{jt,u} a_j
        std::array<std::array<Tensor<1, 3>, 3>, 3> w;
        for (unsigned int t = 0; t < 3; ++t)
          for (unsigned int u = 0; u < 3; ++u)
            {
              Tensor<1, 3> x;
              for (unsigned int f = 0; f < n_f; ++f)
                x += ld.X[3 * face[f] + t][u] * a[face[f]];
              w[t][u] = x;
            }
        const Tensor<2, 3> gg = outer_product(eta, eta);
        // K_tu = sum_jk Phi_{jt,ku} a_j a_k^T
        std::array<std::array<Tensor<2, 3>, 3>, 3> K;
        for (unsigned int t = 0; t < 3; ++t)
          for (unsigned int u = t; u < 3; ++u)
            {
              Tensor<2, 3> Ktu = outer_product(w[t][u], eta) +
                                 outer_product(eta, w[u][t]) + ld.HG[t][u] * gg;
              for (unsigned int f = 0; f < n_f; ++f)
                {
                  const unsigned int j   = face[f];
                  const auto        &row = ld.H[3 * j + t];
                  Tensor<1, 3>       y;
                  for (unsigned int e = 0; e < n_f; ++e)
                    y += row[3 * face[e] + u] * a[face[e]];
                  Ktu += outer_product(a[j], y);
                }
              K[t][u] = Ktu;
              K[u][t] = transpose(Ktu);
            }
        std::array<std::array<Tensor<2, 3>, 3>, 4> R;
        for (unsigned int i = 0; i < 4; ++i)
          for (unsigned int u = 0; u < 3; ++u)
            R[i][u] = L[i][0] * K[0][u] + L[i][1] * K[1][u] + L[i][2] * K[2][u];

        auto      &H   = result.hessian;
        const auto put = [&](const unsigned int  P,
                             const unsigned int  Q,
                             const Tensor<2, 3> &B) {
          for (unsigned int d = 0; d < 3; ++d)
            for (unsigned int e = 0; e < 3; ++e)
              {
                H[3 * P + d][3 * Q + e] = B[d][e];
                H[3 * Q + e][3 * P + d] = B[d][e];
              }
        };
        // the triangle's gradient of Phi, for the product rule with N
        std::array<Tensor<1, 3>, 7> dPhi_x;
        for (unsigned int i = 0; i < 4; ++i)
          dPhi_x[i] = -r[i];
        for (unsigned int t = 0; t < 3; ++t)
          dPhi_x[4 + t] = q[t];
        for (unsigned int k = 0; k < 4; ++k)
          for (unsigned int i = k; i < 4; ++i)
            {
              Tensor<2, 3> B = L[i][0] * R[k][0] + L[i][1] * R[k][1] +
                               L[i][2] * R[k][2] + outer_product(r[i], a[k]) +
                               outer_product(a[i], r[k]);
              put(k, i, cN * B);
            }
        for (unsigned int i = 0; i < 4; ++i)
          for (unsigned int u = 0; u < 3; ++u)
            {
              Tensor<2, 3> B = cN * (-R[i][u] - outer_product(q[u], a[i])) +
                               c * outer_product(dPhi_x[i], area.gradient[u]);
              put(i, 4 + u, B);
            }
        for (unsigned int t = 0; t < 3; ++t)
          for (unsigned int u = t; u < 3; ++u)
            {
              Tensor<2, 3> B = cN * K[t][u] + cPhi * area.hessian[t][u] +
                               c * (outer_product(area.gradient[t], q[u]) +
                                    outer_product(q[t], area.gradient[u]));
              put(4 + t, 4 + u, B);
            }
      }
    } // namespace


    TC_MULTIVERSION bool
    penalty_kernel(const std::array<Point<3>, 4> &tet,
                   const std::array<Point<3>, 3> &tri,
                   const std::array<double, 4>   &g,
                   const double                   eps_p,
                   const bool                     with_hessian,
                   PairKernel                    &result)
    {
      const IntersectionPolygon<double> polygon = intersect(tet, tri);
      const unsigned int                m       = polygon.n_vertices;
      if (m < 3)
        return false;
      const Points x = {
        {tet[0], tet[1], tet[2], tet[3], tri[0], tri[1], tri[2]}};
      // W = c N Phi(Lambda), c = eps_p / 24 (sec. 5.1)
      const Barycentric         bary(x, g);
      TriangleArea              area(tri);
      std::array<ZetaVertex, 9> form;
      FanIntegral               fan;
      fan.n_p = polygon_vertices(polygon, x, bary, area, form);
      fan_integral(form, m, bary, with_hessian, fan);
      const double c = eps_p / 24.;
      if (!(c * area.N * fan.Phi > 0.))
        return false;
      result.energy = c * area.N * fan.Phi;
      area.derivatives(tri, with_hessian);
      LambdaDerivatives ld;
      chain_to_lambda(form, m, fan, with_hessian, ld);
      to_coordinates(bary, area, fan.Phi, ld, c, with_hessian, result);
      return true;
    }


    bool
    collocation_kernel(const std::array<Point<3>, 4> &tet,
                       const std::array<Point<3>, 3> &tri,
                       const std::array<double, 4>   &g,
                       const double                   eps_p,
                       const bool                     with_hessian,
                       PairKernel                    &result)
    {
      const Points x = {
        {tet[0], tet[1], tet[2], tet[3], tri[0], tri[1], tri[2]}};
      const Orientation V = orientation(x, {{0, 1, 2, 3}});
      // W = c A_T sum_k G_k^2 over the vertices inside, c = eps_p / 6
      const double        c = eps_p / 6.;
      std::array<bool, 3> inside{};
      bool                any = false;
      for (unsigned int k = 0; k < 3; ++k)
        {
          const std::array<Point<3>, 3> point = {{tri[k], tri[k], tri[k]}};
          inside[k] = intersect(tet, point).n_vertices > 0;
          any       = any || inside[k];
        }
      if (!any)
        return false;
      // A_T = |N_T| / 2 and its derivatives in the triangle vertices
      TriangleArea area(tri);
      area.derivatives(tri, with_hessian);
      const double A = 0.5 * area.N;
      Vec          grad_A{};
      for (unsigned int X = 0; X < 3; ++X)
        for (unsigned int d = 0; d < 3; ++d)
          grad_A[3 * (4 + X) + d] = 0.5 * area.gradient[X][d];

      double S = 0.; // sum of G_k^2 over the vertices inside, G_k > 0
      Vec    grad_S{};
      std::array<VertexDepth, 3> depth;
      std::array<bool, 3>        active{};
      for (unsigned int k = 0; k < 3; ++k)
        {
          if (!inside[k])
            continue;
          depth[k] = vertex_depth(x, V, g, k);
          if (!(depth[k].G > 0.))
            continue;
          active[k] = true;
          S += depth[k].G * depth[k].G;
          for (unsigned int i = 0; i < n; ++i)
            grad_S[i] += 2. * depth[k].G * depth[k].grad_G[i];
        }
      if (!(S > 0.))
        return false;
      result.energy = c * A * S;
      for (unsigned int i = 0; i < n; ++i)
        result.gradient[i] = c * (S * grad_A[i] + A * grad_S[i]);
      if (!with_hessian)
        return true;

      // c (S Hess A + grad A (x) grad S + grad S (x) grad A + A Hess S)
      Mat &H = result.hessian;
      H      = Mat{};
      // c S Hess A, Hess A = Hess |N_T| / 2
      for (unsigned int X = 0; X < 3; ++X)
        for (unsigned int Y = 0; Y < 3; ++Y)
          for (unsigned int a = 0; a < 3; ++a)
            for (unsigned int b = 0; b < 3; ++b)
              H[3 * (4 + X) + a][3 * (4 + Y) + b] +=
                c * S * 0.5 * area.hessian[X][Y][a][b];
      // the symmetric terms, half of each in Mh (H += Mh + Mh^T below)
      Mat Mh{};
      add_symmetric_outer(Mh, grad_A, grad_S, c);
      // Hess S = sum_k 2 (grad G_k (x) grad G_k + G_k Hess G_k)
      for (unsigned int k = 0; k < 3; ++k)
        if (active[k])
          {
            add_symmetric_outer(Mh,
                                depth[k].grad_G,
                                depth[k].grad_G,
                                2. * c * A * 0.5);
            add_depth_hessian(Mh, x, V, depth[k], g, 2. * c * A * depth[k].G);
          }
      add_symmetrized(H, Mh);
      return true;
    }
  } // namespace Contact
} // namespace TissueContact
