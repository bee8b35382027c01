#include <tissue_contact/base/cross_matrix.h>
#include <tissue_contact/contact/penalty_kernel.h>

#include <algorithm>
#include <cstring>

// Symbols follow doc/theory/05-contact.md, sec. 5.1.

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

        Support() = default;

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

      /** A polygon vertex in closed form: @f$x = (1-s)x_{P_1} + s
       * x_{P_2}@f$, @f$G = (1-s)G_1 + sG_2@f$, @f$s = a/(a-b)@f$ (a, b
       * orientations) unless @p s_varies is false (a triangle vertex, or a
       * degenerate cut where s is a constant). G_i is the depth of triangle
       * vertex @p t_i if t_i < 3, else the constant @p G_const_i. */
      struct VertexForm
      {
        unsigned int P1 = 0, P2 = 0;
        double       s        = 0.;
        bool         s_varies = false;
        Orientation  a, b;
        double       s_a = 0., s_b = 0., s_aa = 0., s_ab = 0., s_bb = 0.;
        Vec          grad_s;
        unsigned int t1 = 3, t2 = 3;
        double       G1 = 0., G2 = 0.;
        Point<3>     x;
        double       G = 0.;
      };

      void
      set_ratio(VertexForm &v, const Orientation &a, const Orientation &b)
      {
        v.a            = a;
        v.b            = b;
        const double d = a.value - b.value;
        v.s            = 0.;
        if (d == 0.)
          return;
        v.s = a.value / d;
        // rounding may disagree with the side decision: the cut then sits
        // at the end point, as in intersect(), but s keeps the derivatives
        // of a / (a - b), the one-sided derivatives in the clipping case
        // intersect() chose (treating the clamped s as a constant dropped
        // them: gradients off by up to 100 % on rotated degenerate pairs)
        v.s        = std::clamp(v.s, 0., 1.);
        v.s_varies = true;
        v.s_a      = -b.value / (d * d);
        v.s_b      = a.value / (d * d);
        v.s_aa     = 2. * b.value / (d * d * d);
        v.s_bb     = 2. * a.value / (d * d * d);
        v.s_ab     = -(a.value + b.value) / (d * d * d);
        v.grad_s.fill(0.);
        add_gradient(v.grad_s, a, v.s_a);
        add_gradient(v.grad_s, b, v.s_b);
      }
    } // namespace


    namespace
    {
      /** Stage 1 of the kernel: the m polygon vertices in closed form from
       * their clipping labels (doc/theory/05-contact.md, sec. 5.1): a
       * triangle vertex, a triangle edge cut by a tetrahedron face, or a
       * tetrahedron edge cut by the triangle's plane; x = (1-s) x_P1 + s
       * x_P2 and G = (1-s) G_1 + s G_2. */
      void
      polygon_vertices(const IntersectionPolygon<double> &polygon,
                       const Points                      &x,
                       const std::array<VertexDepth, 3>  &depth,
                       const std::array<double, 4>       &g,
                       std::array<VertexForm, 9>         &form)
      {
        const unsigned int m = polygon.n_vertices;
        for (unsigned int k = 0; k < m; ++k)
          {
            VertexForm  &v  = form[k];
            unsigned int c1 = polygon.vertex[k].on[0],
                         c2 = polygon.vertex[k].on[1];
            if (c1 > c2)
              std::swap(c1, c2);
            if (c2 < 3)
              {
                // two triangle edges: a triangle vertex
                const unsigned int t = (c2 == c1 + 1) ? c2 : 0;
                v.P1 = v.P2 = 4 + t;
                v.t1 = v.t2 = t;
              }
            else if (c1 < 3)
              {
                // triangle edge c1 cut by face i: s from D_i at its ends
                const unsigned int ta = c1, tb = (c1 + 1) % 3, i = c2 - 3;
                v.P1 = 4 + ta;
                v.P2 = 4 + tb;
                v.t1 = ta;
                v.t2 = tb;
                set_ratio(v, depth[ta].D[i], depth[tb].D[i]);
              }
            else
              {
                // faces i and j: the tetrahedron edge p q cut by the
                // triangle's plane
                unsigned int p = 4, q = 4;
                for (unsigned int r = 0; r < 4; ++r)
                  if (r != c1 - 3 && r != c2 - 3)
                    (p == 4 ? p : q) = r;
                v.P1 = p;
                v.P2 = q;
                v.G1 = g[p];
                v.G2 = g[q];
                set_ratio(v,
                          orientation(x, {{4, 5, 6, p}}),
                          orientation(x, {{4, 5, 6, q}}));
              }
            if (v.t1 < 3)
              {
                v.G1 = depth[v.t1].G;
                v.G2 = depth[v.t2].G;
              }
            v.x = x[v.P1] + v.s * (x[v.P2] - x[v.P1]);
            v.G = (1. - v.s) * v.G1 + v.s * v.G2;
          }
      }


      /** The triangle's unit normal nu = N_T / |N_T| and, once the energy
       * is known to be nonzero, its derivatives: N_T's in the triangle
       * vertices M_X, dnu/dN_T = (I - nu nu^T) / |N_T| and dnu/dt_X. */
      struct TriangleNormal
      {
        Tensor<1, 3>                nu;
        double                      rT = 0.;
        std::array<Tensor<2, 3>, 3> M;
        Tensor<2, 3>                Pnu;
        std::array<Tensor<2, 3>, 3> dnu;

        explicit TriangleNormal(const std::array<Point<3>, 3> &tri)
        {
          const Tensor<1, 3> NT =
            cross_product_3d(tri[1] - tri[0], tri[2] - tri[0]);
          rT = NT.norm();
          nu = NT / rT;
        }

        void
        derivatives(const std::array<Point<3>, 3> &tri)
        {
          M[1] = -cross_matrix(tri[2] - tri[0]);
          M[2] = cross_matrix(tri[1] - tri[0]);
          M[0] = -(M[1] + M[2]);
          Pnu  = -outer_product(nu, nu);
          for (unsigned int d = 0; d < 3; ++d)
            Pnu[d][d] += 1.;
          Pnu /= rT;
          for (unsigned int X = 0; X < 3; ++X)
            dnu[X] = Pnu * M[X];
        }
      };


      /** Stage 2: the fan integral W = c sum_k l_k Q_k, l_k = n_k . nu, and
       * its gradient w and Hessian HP in the primitives: (x, G) of each
       * polygon vertex (4 per vertex), then nu (3). */
      struct FanIntegral
      {
        unsigned int                           m = 0, inu = 0, np = 0;
        double                                 energy = 0.;
        std::array<double, 39>                 w{};
        std::array<std::array<double, 39>, 39> HP;
      };

      void
      fan_integral(const std::array<VertexForm, 9> &form,
                   const unsigned int               m,
                   const TriangleNormal            &normal,
                   const double                     eps_p,
                   const bool                       with_hessian,
                   FanIntegral                     &fan)
      {
        const Tensor<1, 3> &nu = normal.nu;
        const double        c  = eps_p / 24.;
        fan.m                  = m;
        fan.inu                = 4 * m;
        fan.np                 = 4 * m + 3;
        const unsigned int inu = fan.inu, np = fan.np;
        auto              &w      = fan.w;
        auto              &HP     = fan.HP;
        double            &energy = fan.energy;
        // the first np rows whole: one contiguous block, cheaper to zero
        // than np pieces of np entries
        if (with_hessian)
          std::memset(HP.data(), 0, np * sizeof(HP[0]));
        for (unsigned int k = 1; k + 1 < m; ++k)
          {
            const std::array<unsigned int, 3> vtx = {{0, k, k + 1}};
            const Tensor<1, 3>                e1  = form[k].x - form[0].x,
                               e2                 = form[k + 1].x - form[0].x;
            const Tensor<1, 3> nk                 = cross_product_3d(e1, e2);
            const double       l                  = nk * nu;
            const double GA = form[0].G, GB = form[k].G, GC = form[k + 1].G;
            const double Q =
              GA * GA + GB * GB + GC * GC + GA * GB + GB * GC + GC * GA;
            const std::array<double, 3> dQ = {
              {2 * GA + GB + GC, 2 * GB + GA + GC, 2 * GC + GA + GB}};
            energy += c * l * Q;
            // dl/dx_X = N_X^T nu with N_X = dn_k/dx_X
            std::array<Tensor<1, 3>, 3> dl;
            dl[1] = cross_product_3d(e2, nu);
            dl[2] = cross_product_3d(nu, e1);
            dl[0] = -(dl[1] + dl[2]);
            for (unsigned int X = 0; X < 3; ++X)
              {
                for (unsigned int d = 0; d < 3; ++d)
                  w[4 * vtx[X] + d] += c * Q * dl[X][d];
                w[4 * vtx[X] + 3] += c * l * dQ[X];
              }
            for (unsigned int d = 0; d < 3; ++d)
              w[inu + d] += c * Q * nk[d];
            if (!with_hessian)
              continue;
            std::array<Tensor<2, 3>, 3> Nx;
            Nx[1] = -cross_matrix(e2);
            Nx[2] = cross_matrix(e1);
            Nx[0] = -(Nx[1] + Nx[2]);
            // l is bilinear in (e1, e2): d2l = nu . (de1 x de2), the blocks
            // (A,B), (B,C), (C,A) are -[nu]_x, their transposes [nu]_x
            const Tensor<2, 3> Bm = -cross_matrix(nu);
            for (unsigned int X = 0; X < 3; ++X)
              {
                const unsigned int i = 4 * vtx[X];
                for (unsigned int Y = 0; Y < 3; ++Y)
                  {
                    const unsigned int j    = 4 * vtx[Y];
                    const double       sign = (Y + 3 - X) % 3 == 1 ? 1. :
                                              (X + 3 - Y) % 3 == 1 ? -1. :
                                                                     0.;
                    for (unsigned int p = 0; p < 3; ++p)
                      {
                        if (sign != 0.)
                          for (unsigned int q = 0; q < 3; ++q)
                            HP[i + p][j + q] += sign * c * Q * Bm[p][q];
                        HP[i + p][j + 3] += c * dl[X][p] * dQ[Y];
                        HP[j + 3][i + p] += c * dl[X][p] * dQ[Y];
                      }
                    HP[i + 3][j + 3] += c * l * (X == Y ? 2. : 1.);
                  }
                // (x_X, nu): c Q N_X^T; (G_X, nu): c dQ_X n_k
                for (unsigned int p = 0; p < 3; ++p)
                  for (unsigned int q = 0; q < 3; ++q)
                    {
                      HP[i + p][inu + q] += c * Q * Nx[X][q][p];
                      HP[inu + q][i + p] += c * Q * Nx[X][q][p];
                    }
                for (unsigned int q = 0; q < 3; ++q)
                  {
                    HP[i + 3][inu + q] += c * dQ[X] * nk[q];
                    HP[inu + q][i + 3] += c * dQ[X] * nk[q];
                  }
              }
          }
      }


      /** The weights the chain rule needs twice: omega_t of the depths G_t
       * of the triangle vertices and sigma_k = dW/ds_k of the cut ratios. */
      struct ChainWeights
      {
        std::array<double, 3> omega{};
        std::array<double, 9> sigma{};
      };

      /** Stage 3: the gradient in the 21 coordinates by the chain rule
       * through the polygon vertices, the depths G_t and the normal. */
      void
      chain_gradient(const std::array<VertexForm, 9>  &form,
                     const Points                     &x,
                     const std::array<VertexDepth, 3> &depth,
                     const TriangleNormal             &normal,
                     const FanIntegral                &fan,
                     ChainWeights                     &cw,
                     Vec                              &grad)
      {
        const unsigned int m = fan.m, inu = fan.inu;
        const auto        &w     = fan.w;
        auto              &omega = cw.omega;
        auto              &sigma = cw.sigma;
        const auto        &dnu   = normal.dnu;
        grad.fill(0.);
        for (unsigned int k = 0; k < m; ++k)
          {
            const VertexForm &v = form[k];
            for (unsigned int d = 0; d < 3; ++d)
              {
                grad[3 * v.P1 + d] += (1. - v.s) * w[4 * k + d];
                grad[3 * v.P2 + d] += v.s * w[4 * k + d];
              }
            const double wG = w[4 * k + 3];
            if (v.t1 < 3)
              {
                omega[v.t1] += (1. - v.s) * wG;
                omega[v.t2] += v.s * wG;
              }
            if (v.s_varies)
              {
                sigma[k] = wG * (v.G2 - v.G1);
                for (unsigned int d = 0; d < 3; ++d)
                  sigma[k] += w[4 * k + d] * (x[v.P2][d] - x[v.P1][d]);
                for (unsigned int i = 0; i < n; ++i)
                  grad[i] += sigma[k] * v.grad_s[i];
              }
          }
        for (unsigned int t = 0; t < 3; ++t)
          if (omega[t] != 0.)
            for (unsigned int i = 0; i < n; ++i)
              grad[i] += omega[t] * depth[t].grad_G[i];
        const Tensor<1, 3> w_nu({w[inu], w[inu + 1], w[inu + 2]});
        for (unsigned int X = 0; X < 3; ++X)
          {
            const Tensor<1, 3> gX = transpose(dnu[X]) * w_nu;
            for (unsigned int d = 0; d < 3; ++d)
              grad[3 * (4 + X) + d] += gX[d];
          }
      }


      /** Stage 4: the Hessian by the chain rule in two levels
       * (doc/theory/05-contact.md, sec. 5.1, level 2): the primitives are
       * simple functions of z = (the 21 coordinates, the cut ratios s_k,
       * the depths G_t, the normal nu), z of the coordinates; H = Z^T Hz Z
       * plus the first-derivative terms of s_k, G_t and nu. */
      void
      chain_hessian(const std::array<VertexForm, 9>  &form,
                    const Points                     &x,
                    const Orientation                &V,
                    const std::array<VertexDepth, 3> &depth,
                    const std::array<double, 4>      &g,
                    const TriangleNormal             &normal,
                    const FanIntegral                &fan,
                    const ChainWeights               &cw,
                    Mat                              &H)
      {
        const unsigned int m = fan.m, inu = fan.inu, np = fan.np;
        const auto        &w     = fan.w;
        const auto        &HP    = fan.HP;
        const auto        &omega = cw.omega;
        const auto        &sigma = cw.sigma;
        const auto        &nu    = normal.nu;
        const double       rT    = normal.rT;
        const auto        &M     = normal.M;
        const auto        &Pnu   = normal.Pnu;
        const auto        &dnu   = normal.dnu;
        const Tensor<1, 3> w_nu({w[inu], w[inu + 1], w[inu + 2]});

        // z: the 21 coordinates, then s_k (k < m), G_t (t < 3), nu (3)
        const unsigned int zs = n, zG = n + m, znu = n + m + 3,
                           q = m + 6; // the z beyond the coordinates
        // dz/dprimitive: at most 3 (z, coefficient) entries per primitive
        struct Entry
        {
          unsigned int z;
          double       c;
        };
        std::array<std::array<Entry, 3>, 39> L;
        std::array<unsigned int, 39>         nL{};
        for (unsigned int k = 0; k < m; ++k)
          {
            const VertexForm &v = form[k];
            for (unsigned int d = 0; d < 3; ++d)
              {
                auto &e = L[4 * k + d];
                auto &l = nL[4 * k + d];
                e[l++]  = {3 * v.P1 + d, 1. - v.s};
                if (v.P2 != v.P1)
                  e[l++] = {3 * v.P2 + d, v.s};
                if (v.s_varies)
                  e[l++] = {zs + k, x[v.P2][d] - x[v.P1][d]};
              }
            auto &e = L[4 * k + 3];
            auto &l = nL[4 * k + 3];
            if (v.t1 < 3)
              {
                e[l++] = {zG + v.t1, 1. - v.s};
                if (v.t2 != v.t1)
                  e[l++] = {zG + v.t2, v.s};
              }
            if (v.s_varies)
              e[l++] = {zs + k, v.G2 - v.G1};
          }
        for (unsigned int d = 0; d < 3; ++d)
          {
            L[inu + d][0] = {znu + d, 1.};
            nL[inu + d]   = 1;
          }

        // Hz = (dprimitive/dz)^T HP (dprimitive/dz) + the primitives'
        // second derivatives in z, weighted by w: x_k and G_k are bilinear
        // in s_k and their end values
        std::array<std::array<double, 36>, 36> Hz;
        const unsigned int                     nz = n + q;
        std::memset(Hz.data(), 0, nz * sizeof(Hz[0])); // nz whole rows
        for (unsigned int a = 0; a < np; ++a)
          for (unsigned int b = 0; b < np; ++b)
            {
              const double h = HP[a][b];
              if (h == 0.)
                continue;
              for (unsigned int p = 0; p < nL[a]; ++p)
                {
                  const double ha  = L[a][p].c * h;
                  auto        &row = Hz[L[a][p].z];
                  for (unsigned int r = 0; r < nL[b]; ++r)
                    row[L[b][r].z] += ha * L[b][r].c;
                }
            }
        for (unsigned int k = 0; k < m; ++k)
          {
            const VertexForm &v = form[k];
            if (!v.s_varies)
              continue;
            const auto add = [&](const unsigned int j, const double c) {
              Hz[zs + k][j] += c;
              Hz[j][zs + k] += c;
            };
            for (unsigned int d = 0; d < 3; ++d)
              {
                add(3 * v.P2 + d, w[4 * k + d]);
                add(3 * v.P1 + d, -w[4 * k + d]);
              }
            if (v.t1 < 3)
              {
                add(zG + v.t2, w[4 * k + 3]);
                add(zG + v.t1, -w[4 * k + 3]);
              }
          }

        // Z = dz/dcoordinates: the identity, then the columns grad s_k,
        // grad G_t, dnu_d, each zero outside a few points
        std::array<const Vec *, 15> Zc{};
        std::array<Support, 15>     Zs;
        Vec                         dnu_col[3];
        for (unsigned int k = 0; k < m; ++k)
          if (form[k].s_varies)
            {
              const VertexForm           &v = form[k];
              std::array<unsigned int, 8> P;
              std::copy(v.a.point.begin(), v.a.point.end(), P.begin());
              std::copy(v.b.point.begin(), v.b.point.end(), P.begin() + 4);
              Zc[k] = &v.grad_s;
              Zs[k] = Support(P);
            }
        for (unsigned int t = 0; t < 3; ++t)
          {
            Zc[m + t] = &depth[t].grad_G;
            Zs[m + t] = Support(depth[t].points);
          }
        for (unsigned int d = 0; d < 3; ++d)
          {
            dnu_col[d].fill(0.);
            for (unsigned int X = 0; X < 3; ++X)
              for (unsigned int e = 0; e < 3; ++e)
                dnu_col[d][3 * (4 + X) + e] = dnu[X][d][e];
            Zc[m + 3 + d] = &dnu_col[d];
            Zs[m + 3 + d] = Support(std::array<unsigned int, 3>{{4, 5, 6}});
          }

        // H = A + Mh + Mh^T, Mh = Z U^T + (half of the first-derivative
        // terms below), U = B + Z C / 2 with Hz = [A B; B^T C]. U is kept
        // transposed and Mh row by row, so that the inner loops run over
        // 21 contiguous entries
        std::array<Vec, 15> Ut;
        for (unsigned int j = 0; j < q; ++j)
          std::copy(Hz[n + j].begin(), Hz[n + j].begin() + n, Ut[j].begin());
        for (unsigned int l = 0; l < q; ++l)
          if (Zc[l] != nullptr)
            {
              const Vec &z = *Zc[l];
              for (unsigned int j = 0; j < q; ++j)
                {
                  const double c = 0.5 * Hz[n + j][n + l];
                  if (c != 0.)
                    for (unsigned int i = 0; i < n; ++i)
                      Ut[j][i] += c * z[i];
                }
            }
        Mat Mh{}; // zero (one block)
        for (unsigned int j = 0; j < q; ++j)
          if (Zc[j] != nullptr)
            {
              const Vec &z = *Zc[j];
              for (unsigned int p = 0; p < Zs[j].size; ++p)
                {
                  const unsigned int k  = Zs[j].i[p];
                  const double       zk = z[k];
                  for (unsigned int i = 0; i < n; ++i)
                    Mh[k][i] += zk * Ut[j][i];
                }
            }

        // + sum_k sigma_k Hess s_k
        for (unsigned int k = 0; k < m; ++k)
          {
            const VertexForm &v = form[k];
            if (!v.s_varies)
              continue;
            add_hessian(Mh, x, v.a, sigma[k] * v.s_a);
            add_hessian(Mh, x, v.b, sigma[k] * v.s_b);
            Vec ga{}, gb{};
            add_gradient(ga, v.a, 1.);
            add_gradient(gb, v.b, 1.);
            const Support sa = support(v.a), sb = support(v.b);
            add_symmetric_outer(Mh, ga, sa, ga, sa, 0.5 * sigma[k] * v.s_aa);
            add_symmetric_outer(Mh, ga, sa, gb, sb, sigma[k] * v.s_ab);
            add_symmetric_outer(Mh, gb, sb, gb, sb, 0.5 * sigma[k] * v.s_bb);
          }
        // + sum_t omega_t Hess G_t, G_t = N_t / V
        for (unsigned int t = 0; t < 3; ++t)
          if (omega[t] != 0.)
            add_depth_hessian(Mh, x, V, depth[t], g, omega[t]);
        for (unsigned int i = 0; i < n; ++i)
          std::copy(Hz[i].begin(), Hz[i].begin() + n, H[i].begin());
        add_symmetrized(H, Mh);
        // + Hess(w_nu . nu): with phi(N) = w_nu . N / |N|, p = dphi/dN,
        // M^T (d2phi/dN2) M + the bilinear part p . (dE1 x dE2)
        {
          const Tensor<1, 3> p   = Pnu * w_nu;
          const double       wn  = w_nu * nu;
          Tensor<2, 3>       Phi = 3. * wn * outer_product(nu, nu) -
                             outer_product(w_nu, nu) - outer_product(nu, w_nu);
          for (unsigned int d = 0; d < 3; ++d)
            Phi[d][d] -= wn;
          Phi /= rT * rT;
          const Tensor<2, 3> Bp = -cross_matrix(p);
          for (unsigned int X = 0; X < 3; ++X)
            for (unsigned int Y = 0; Y < 3; ++Y)
              {
                Tensor<2, 3> block = transpose(M[X]) * Phi * M[Y];
                if ((Y + 3 - X) % 3 == 1)
                  block += Bp;
                else if ((X + 3 - Y) % 3 == 1)
                  block -= Bp;
                for (unsigned int a = 0; a < 3; ++a)
                  for (unsigned int b = 0; b < 3; ++b)
                    H[3 * (4 + X) + a][3 * (4 + Y) + b] += block[a][b];
              }
        }
      }
    } // namespace


    bool
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

      // depth field at the triangle vertices (sec. 5.1, G_t)
      const Orientation                V     = orientation(x, {{0, 1, 2, 3}});
      const std::array<VertexDepth, 3> depth = {{vertex_depth(x, V, g, 0),
                                                 vertex_depth(x, V, g, 1),
                                                 vertex_depth(x, V, g, 2)}};
      // clip labels -> polygon vertices -> fan integral -> chain rule
      std::array<VertexForm, 9> form;
      polygon_vertices(polygon, x, depth, g, form);
      TriangleNormal normal(tri);
      FanIntegral    fan;
      fan_integral(form, m, normal, eps_p, with_hessian, fan);
      if (!(fan.energy > 0.))
        return false;
      result.energy = fan.energy;
      normal.derivatives(tri);
      ChainWeights cw;
      chain_gradient(form, x, depth, normal, fan, cw, result.gradient);
      if (with_hessian)
        chain_hessian(form, x, V, depth, g, normal, fan, cw, result.hessian);
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
      const Tensor<1, 3>          E1 = tri[1] - tri[0], E2 = tri[2] - tri[0];
      const Tensor<1, 3>          NT = cross_product_3d(E1, E2);
      const double                rT = NT.norm();
      const Tensor<1, 3>          nu = NT / rT;
      const double                A  = 0.5 * rT;
      std::array<Tensor<2, 3>, 3> M;
      M[1] = -cross_matrix(E2);
      M[2] = cross_matrix(E1);
      M[0] = -(M[1] + M[2]);
      Vec grad_A{};
      for (unsigned int X = 0; X < 3; ++X)
        {
          const Tensor<1, 3> gX = 0.5 * (transpose(M[X]) * nu);
          for (unsigned int d = 0; d < 3; ++d)
            grad_A[3 * (4 + X) + d] = gX[d];
        }

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
      {
        // Hess |N_T| = M^T (I - nu nu^T) M / |N_T| + bilinear part of N_T
        // weighted by nu; A = |N_T| / 2
        Tensor<2, 3> P = -outer_product(nu, nu);
        for (unsigned int d = 0; d < 3; ++d)
          P[d][d] += 1.;
        const Tensor<2, 3> Bn = -cross_matrix(nu);
        for (unsigned int X = 0; X < 3; ++X)
          for (unsigned int Y = 0; Y < 3; ++Y)
            {
              Tensor<2, 3> block = transpose(M[X]) * P * M[Y] / rT;
              if ((Y + 3 - X) % 3 == 1)
                block += Bn;
              else if ((X + 3 - Y) % 3 == 1)
                block -= Bn;
              for (unsigned int a = 0; a < 3; ++a)
                for (unsigned int b = 0; b < 3; ++b)
                  H[3 * (4 + X) + a][3 * (4 + Y) + b] +=
                    c * S * 0.5 * block[a][b];
            }
      }
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
