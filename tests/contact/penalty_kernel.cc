// The triangle-tetrahedron penalty kernel over random configurations:
//  - the intersection area equals an independent estimate (the fraction of
//    a fine grid of sample points of the triangle inside the tetrahedron);
//  - the gradient and Hessian (automatic differentiation) equal finite
//    differences of the energy and of the gradient;
//  - the Hessian is symmetric, the 7 node forces sum to zero and have no
//    net torque, the energy is invariant under rigid motions;
//  - degenerate positions (a triangle vertex on a face shared by two
//    tetrahedra, an edge or the whole triangle in it, through an edge,
//    touching a vertex) give finite values, no NaN, and a continuous
//    energy of the pair of tetrahedra.

#include "../tests.h"

#include <tissue_contact/contact/ad_reference.h>
#include <tissue_contact/contact/penalty_energy.h>
#include <tissue_contact/contact/penalty_kernel.h>
#include <tissue_contact/contact/point_collocation.h>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

namespace
{
  /** The automatic-differentiation references of the two pair energies. */
  Contact::PairDerivatives
  penalty_ad(const std::array<Point<3>, 4> &tet,
             const std::array<Point<3>, 3> &tri,
             const std::array<double, 4>   &g,
             const double                   eps_p)
  {
    return Contact::ad_derivatives(
      [&](const auto &K, const auto &T) {
        return Contact::penalty_energy(K, T, g, eps_p);
      },
      true,
      tet,
      tri);
  }

  Contact::PairDerivatives
  collocation_ad(const std::array<Point<3>, 4> &tet,
                 const std::array<Point<3>, 3> &tri,
                 const std::array<double, 4>   &g,
                 const double                   eps_p)
  {
    return Contact::ad_derivatives(
      [&](const auto &K, const auto &T) {
        return Contact::collocation_energy(K, T, g, eps_p);
      },
      true,
      tet,
      tri);
  }

  using Tet = std::array<Point<3>, 4>;
  using Tri = std::array<Point<3>, 3>;

  Point<3>
  random_point(const double r)
  {
    return Point<3>(random_value(-r, r),
                    random_value(-r, r),
                    random_value(-r, r));
  }

  Tet
  random_tet()
  {
    while (true)
      {
        Tet          t{random_point(1),
              random_point(1),
              random_point(1),
              random_point(1)};
        const double v =
          (t[1] - t[0]) * cross_product_3d(t[2] - t[0], t[3] - t[0]);
        if (std::abs(v) < 0.3)
          continue;
        if (v < 0)
          std::swap(t[1], t[2]);
        return t;
      }
  }

  std::array<double, 4>
  random_depths()
  {
    return {random_value(0, 0.5),
            random_value(0, 0.5),
            random_value(0, 0.5),
            random_value(0, 0.5)};
  }

  double
  energy_of(const std::vector<double> &c, const std::array<double, 4> &g)
  {
    Tet tet;
    Tri tri;
    for (unsigned v = 0; v < 4; ++v)
      tet[v] = Point<3>(c[3 * v], c[3 * v + 1], c[3 * v + 2]);
    for (unsigned v = 0; v < 3; ++v)
      tri[v] = Point<3>(c[12 + 3 * v], c[13 + 3 * v], c[14 + 3 * v]);
    return Contact::penalty_energy<double>(tet, tri, g, 10.);
  }

  Contact::PairDerivatives
  derivatives_of(const std::vector<double> &c, const std::array<double, 4> &g)
  {
    Tet tet;
    Tri tri;
    for (unsigned v = 0; v < 4; ++v)
      tet[v] = Point<3>(c[3 * v], c[3 * v + 1], c[3 * v + 2]);
    for (unsigned v = 0; v < 3; ++v)
      tri[v] = Point<3>(c[12 + 3 * v], c[13 + 3 * v], c[14 + 3 * v]);
    return penalty_ad(tet, tri, g, 10.);
  }

  /** The hand-derived kernel, in the reference's storage. */
  Contact::PairDerivatives
  hand_derivatives_of(const std::vector<double>   &c,
                      const std::array<double, 4> &g)
  {
    Tet tet;
    Tri tri;
    for (unsigned v = 0; v < 4; ++v)
      tet[v] = Point<3>(c[3 * v], c[3 * v + 1], c[3 * v + 2]);
    for (unsigned v = 0; v < 3; ++v)
      tri[v] = Point<3>(c[12 + 3 * v], c[13 + 3 * v], c[14 + 3 * v]);
    Contact::PairKernel      k;
    Contact::PairDerivatives d;
    d.gradient.reinit(21);
    d.hessian.reinit(21, 21);
    if (Contact::penalty_kernel(tet, tri, g, 10., true, k))
      {
        d.energy = k.energy;
        for (unsigned int i = 0; i < 21; ++i)
          {
            d.gradient[i] = k.gradient[i];
            for (unsigned int j = 0; j < 21; ++j)
              d.hessian(i, j) = k.hessian[i][j];
          }
      }
    return d;
  }

  std::vector<double>
  coordinates(const Tet &tet, const Tri &tri)
  {
    std::vector<double> c;
    for (const auto &p : tet)
      for (unsigned d = 0; d < 3; ++d)
        c.push_back(p[d]);
    for (const auto &p : tri)
      for (unsigned d = 0; d < 3; ++d)
        c.push_back(p[d]);
    return c;
  }

  void
  area_against_sampling()
  {
    double       max_error = 0.;
    unsigned int n_cut     = 0;
    const int    n         = 300; // sub-triangles per edge
    for (unsigned int sample = 0; sample < 100; ++sample)
      {
        const Tet    tet  = random_tet();
        const Tri    tri  = {random_point(1), random_point(1), random_point(1)};
        const double area = Contact::intersection_area(tet, tri);
        // centroids of the n^2 congruent sub-triangles, each of area A/n^2
        const Tensor<1, 3> e1 = (tri[1] - tri[0]) / n,
                           e2 = (tri[2] - tri[0]) / n;
        const double A =
          0.5 * cross_product_3d(tri[1] - tri[0], tri[2] - tri[0]).norm();
        const auto inside = [&](const Point<3> &p) {
          const Tensor<1, 3> a = tet[1] - tet[0], b = tet[2] - tet[0],
                             c = tet[3] - tet[0], r = p - tet[0];
          const double V  = a * cross_product_3d(b, c);
          const double l1 = r * cross_product_3d(b, c) / V,
                       l2 = a * cross_product_3d(r, c) / V,
                       l3 = a * cross_product_3d(b, r) / V;
          return l1 >= 0 && l2 >= 0 && l3 >= 0 && l1 + l2 + l3 <= 1;
        };
        unsigned long count = 0;
        for (int i = 0; i < n; ++i)
          for (int j = 0; i + j < n; ++j)
            {
              const Point<3> corner = tri[0] + i * e1 + j * e2;
              count += inside(corner + (e1 + e2) / 3.);
              if (i + j < n - 1)
                count += inside(corner + 2. * (e1 + e2) / 3.);
            }
        const double estimate = A * count / (double(n) * n);
        n_cut += (area > 0.);
        max_error = std::max(max_error, std::abs(area - estimate) / A);
      }
    deallog << "intersection area vs sampling (100 random pairs, " << n_cut
            << " intersecting): max |difference| / triangle area "
            << error_bound(max_error, -4) << std::endl;
  }

  void
  derivatives_against_fd()
  {
    double err_g = 0., err_h = 0., asym = 0., force = 0., torque = 0.,
           rigid       = 0.;
    unsigned int n_cut = 0, n_vertices_max = 0;
    for (unsigned int sample = 0; n_cut < 300; ++sample)
      {
        const Tet tet = random_tet();
        // a triangle through the tetrahedron's neighbourhood
        const Tri  tri = {random_point(0.8),
                          random_point(0.8),
                          random_point(0.8)};
        const auto g   = random_depths();
        const auto c   = coordinates(tet, tri);
        const auto d   = derivatives_of(c, g);
        if (d.energy <= 0.)
          continue;
        ++n_cut;
        n_vertices_max =
          std::max(n_vertices_max, Contact::intersect(tet, tri).n_vertices);

        const double       h = 1e-6;
        Vector<double>     g_fd(21);
        FullMatrix<double> H_fd(21, 21);
        for (unsigned int i = 0; i < 21; ++i)
          {
            auto cp = c, cm = c;
            cp[i] += h;
            cm[i] -= h;
            g_fd[i]       = (energy_of(cp, g) - energy_of(cm, g)) / (2 * h);
            const auto dp = derivatives_of(cp, g), dm = derivatives_of(cm, g);
            for (unsigned int j = 0; j < 21; ++j)
              H_fd(j, i) = (dp.gradient[j] - dm.gradient[j]) / (2 * h);
          }
        Vector<double> dg(d.gradient);
        dg -= g_fd;
        err_g = std::max(err_g, dg.l2_norm() / d.gradient.l2_norm());
        FullMatrix<double> dH(d.hessian);
        dH.add(-1., H_fd);
        err_h =
          std::max(err_h, dH.frobenius_norm() / d.hessian.frobenius_norm());
        for (unsigned int i = 0; i < 21; ++i)
          for (unsigned int j = 0; j < 21; ++j)
            asym = std::max(asym,
                            std::abs(d.hessian(i, j) - d.hessian(j, i)) /
                              d.hessian.linfty_norm());

        // balance of the 7 node forces f_a = -dW/dx_a
        Tensor<1, 3> sum, moment;
        for (unsigned int a = 0; a < 7; ++a)
          {
            const Tensor<1, 3> f({d.gradient[3 * a],
                                  d.gradient[3 * a + 1],
                                  d.gradient[3 * a + 2]});
            const Point<3>     x(c[3 * a], c[3 * a + 1], c[3 * a + 2]);
            sum += f;
            moment += cross_product_3d(x, f);
          }
        force  = std::max(force, sum.norm() / d.gradient.l2_norm());
        torque = std::max(torque, moment.norm() / d.gradient.l2_norm());

        // rigid motion of the pair: rotation about a random axis + shift
        Tensor<1, 3> axis(
          {random_value(-1, 1), random_value(-1, 1), random_value(-1, 1)});
        axis /= axis.norm();
        const double       angle = random_value(0, 6.28);
        const Tensor<1, 3> shift(
          {random_value(-5, 5), random_value(-5, 5), random_value(-5, 5)});
        auto moved = c;
        for (unsigned int a = 0; a < 7; ++a)
          {
            const Tensor<1, 3> x({c[3 * a], c[3 * a + 1], c[3 * a + 2]});
            const Tensor<1, 3> y = std::cos(angle) * x +
                                   std::sin(angle) * cross_product_3d(axis, x) +
                                   (1 - std::cos(angle)) * (axis * x) * axis +
                                   shift;
            for (unsigned d2 = 0; d2 < 3; ++d2)
              moved[3 * a + d2] = y[d2];
          }
        rigid =
          std::max(rigid, std::abs(energy_of(moved, g) - d.energy) / d.energy);
      }
    deallog << n_cut << " random intersecting pairs (up to " << n_vertices_max
            << " polygon vertices):" << std::endl;
    deallog << "  gradient vs FD of the energy: relative error "
            << error_bound(err_g, -12) << std::endl;
    deallog << "  Hessian vs FD of the gradient: relative error "
            << error_bound(err_h, -12) << std::endl;
    deallog << "  Hessian asymmetry " << error_bound(asym, -14) << std::endl;
    deallog << "  sum of the 7 node forces " << error_bound(force, -12)
            << ", net torque " << error_bound(torque, -12) << std::endl;
    deallog << "  energy change under a rigid motion "
            << error_bound(rigid, -12) << std::endl;
  }

  /**
   * A triangle near the tetrahedron; @p kind picks a near-degenerate
   * family: 0 generic, 1 a triangle vertex on a face, 2 a triangle vertex
   * on an edge, 3 a triangle vertex at a tetrahedron vertex, 4 the
   * triangle in a face plane; positions within @p offset of exact.
   */
  Tri
  triangle_near(const Tet &tet, const unsigned int kind, const double offset)
  {
    Tri        tri = {random_point(0.8), random_point(0.8), random_point(0.8)};
    const auto on_tet = [&](std::array<double, 4> lambda) {
      double sum = 0.;
      for (auto &l : lambda)
        sum += l;
      Point<3> p;
      for (unsigned int j = 0; j < 4; ++j)
        p += lambda[j] / sum * tet[j];
      return p + random_point(offset);
    };
    const double a = random_value(0, 1), b = random_value(0, 1),
                 c               = random_value(0, 1);
    const unsigned int    i      = std::min(3, int(random_value(0, 4)));
    std::array<double, 4> lambda = {a, b, c, random_value(0, 1)};
    switch (kind)
      {
        case 1:
          lambda[i] = 0.;
          tri[0]    = on_tet(lambda);
          break;
        case 2:
          lambda[i]           = 0.;
          lambda[(i + 1) % 4] = 0.;
          tri[0]              = on_tet(lambda);
          break;
        case 3:
          tri[0] = tet[i] + random_point(offset);
          break;
        case 4:
          for (auto &p : tri)
            {
              std::array<double, 4> l = {random_value(-0.3, 1),
                                         random_value(-0.3, 1),
                                         random_value(-0.3, 1),
                                         random_value(-0.3, 1)};
              l[i]                    = 0.;
              p                       = on_tet(l);
            }
          break;
        default:
          break;
      }
    return tri;
  }

  /**
   * The hand-derived kernel against the AD reference on 600 intersecting
   * pairs per family, 1e-6 from the degenerate position (both are smooth
   * there; the derivatives of the cut ratios grow like 1/offset^k, so the
   * agreement is the conditioning's), then at the degenerate position
   * itself (within rounding), where the energy has a kink and the two
   * may pick different one-sided derivatives: there the energies must
   * agree and everything must be finite. Near edges and vertices the
   * reference loses digits (its clipping cuts sub-segments 1e-6 long);
   * the hand kernel's Hessian is checked against central differences of
   * its own gradient (step 1e-9) on the first 100 pairs of each family.
   */
  void
  hand_kernel_against_ad()
  {
    static const char *names[] = {"generic",
                                  "vertex near a face",
                                  "vertex near an edge",
                                  "vertex near a vertex",
                                  "triangle near a face plane"};
    // smallest exponents printed (energy, gradient, Hessian) per family
    static const int exponents[5][3] = {{-12, -10, -8},
                                        {-12, -10, -8},
                                        {-12, -6, -1},
                                        {-12, -6, -1},
                                        {-6, -2, 0}};
    for (const double offset : {1e-6, 0.})
      for (unsigned int kind = (offset == 0. ? 1 : 0); kind < 5; ++kind)
        {
          double       err_e = 0., err_g = 0., err_h = 0.;
          unsigned int n_fd_agree = 0;
          unsigned int n_cut      = 0;
          bool         finite     = true;
          while (n_cut < 600)
            {
              const Tet  tet = random_tet();
              const Tri  tri = triangle_near(tet, kind, offset);
              const auto g   = random_depths();
              const auto c   = coordinates(tet, tri);
              const auto ad  = derivatives_of(c, g);
              const auto h   = hand_derivatives_of(c, g);
              finite         = finite && std::isfinite(h.energy) &&
                       std::isfinite(h.gradient.l2_norm()) &&
                       std::isfinite(h.hessian.frobenius_norm());
              if (ad.energy <= 0. && h.energy <= 0.)
                continue;
              ++n_cut;
              // errors relative to the pair's scale eps A_T max(g)^2 (the
              // lengths are of order one), so that rounding-level slivers
              // (energies of 1e-30) compare absolutely
              const double scale =
                10. * 0.5 *
                cross_product_3d(tri[1] - tri[0], tri[2] - tri[0]).norm() *
                std::pow(*std::max_element(g.begin(), g.end()), 2);
              err_e = std::max(err_e,
                               std::abs(h.energy - ad.energy) /
                                 std::max(ad.energy, scale));
              Vector<double> dg(h.gradient);
              dg -= ad.gradient;
              err_g =
                std::max(err_g,
                         dg.l2_norm() / std::max(ad.gradient.l2_norm(), scale));
              FullMatrix<double> dH(h.hessian);
              dH.add(-1., ad.hessian);
              err_h = std::max(err_h,
                               dH.frobenius_norm() /
                                 std::max(ad.hessian.frobenius_norm(), scale));
              if (offset > 0. && n_cut <= 100)
                {
                  const double       step = 1e-9;
                  FullMatrix<double> H_fd(21, 21);
                  for (unsigned int i = 0; i < 21; ++i)
                    {
                      auto cp = c, cm = c;
                      cp[i] += step;
                      cm[i] -= step;
                      const auto hp = hand_derivatives_of(cp, g),
                                 hm = hand_derivatives_of(cm, g);
                      for (unsigned int j = 0; j < 21; ++j)
                        H_fd(j, i) =
                          (hp.gradient[j] - hm.gradient[j]) / (2 * step);
                    }
                  H_fd.add(-1., h.hessian);
                  // a step across a change of the clipping's case (within
                  // 1e-9 of it) gives an O(1) difference: count agreements
                  n_fd_agree +=
                    H_fd.frobenius_norm() <
                    1e-3 * std::max(h.hessian.frobenius_norm(), scale);
                }
            }
          deallog << "hand kernel vs AD, " << names[kind];
          if (offset == 0.)
            deallog << ", exactly (" << n_cut << " pairs): energy "
                    << error_bound(err_e, -12) << ", all finite " << finite
                    << std::endl;
          else
            deallog
              << " (" << n_cut << " pairs): energy "
              << error_bound(err_e, exponents[kind][0]) << ", gradient "
              << error_bound(err_g, exponents[kind][1]) << ", Hessian "
              << error_bound(err_h, exponents[kind][2])
              << "; its Hessian agrees with FD of its gradient to 1e-3 on "
              << n_fd_agree << " of 100, all finite " << finite << std::endl;
        }
  }

  /** The hand-derived point-collocation kernel against its AD reference. */
  void
  collocation_against_ad()
  {
    double       err_g = 0., err_h = 0., err_e = 0.;
    unsigned int n_cut = 0;
    while (n_cut < 300)
      {
        const Tet           tet = random_tet();
        const Tri           tri = {random_point(0.8),
                                   random_point(0.8),
                                   random_point(0.8)};
        const auto          g   = random_depths();
        const auto          ad  = collocation_ad(tet, tri, g, 10.);
        Contact::PairKernel k;
        const bool hit = Contact::collocation_kernel(tet, tri, g, 10., true, k);
        if (!(ad.energy > 0.) && !hit)
          continue;
        ++n_cut;
        err_e     = std::max(err_e, std::abs(k.energy - ad.energy) / ad.energy);
        double dg = 0., dh = 0.;
        for (unsigned int i = 0; i < 21; ++i)
          {
            dg += std::pow(k.gradient[i] - ad.gradient[i], 2);
            for (unsigned int j = 0; j < 21; ++j)
              dh += std::pow(k.hessian[i][j] - ad.hessian(i, j), 2);
          }
        err_g = std::max(err_g, std::sqrt(dg) / ad.gradient.l2_norm());
        err_h = std::max(err_h, std::sqrt(dh) / ad.hessian.frobenius_norm());
      }
    deallog << "point collocation, hand kernel vs AD (" << n_cut
            << " pairs): energy " << error_bound(err_e, -12) << ", gradient "
            << error_bound(err_g, -10) << ", Hessian " << error_bound(err_h, -8)
            << std::endl;
  }

  void
  degenerate_positions()
  {
    // a tetrahedron and its mirror image through the face z = 0, with equal
    // depths on the shared face: a triangle on that face is owned by
    // exactly one of the two, so the sum is what must be continuous
    const Point<3> A(0, 0, 0), B(1, 0, 0), C(0, 1, 0);
    const std::array<std::pair<Tet, std::array<double, 4>>, 2> tets = {
      std::make_pair(Tet{A, B, C, Point<3>(0, 0, 1)},
                     std::array<double, 4>{0.3, 0., 0.1, 0.2}),
      std::make_pair(Tet{A, C, B, Point<3>(0, 0, -1)},
                     std::array<double, 4>{0.3, 0.1, 0., 0.25})};
    const std::vector<std::pair<std::string, Tri>> cases = {
      {"triangle vertex on the shared face",
       {Point<3>(0.2, 0.2, 0.),
        Point<3>(0.3, 0.2, 0.5),
        Point<3>(0.2, 0.4, 0.5)}},
      {"triangle edge in the shared face",
       {Point<3>(0.1, 0.1, 0.),
        Point<3>(0.5, 0.2, 0.),
        Point<3>(0.2, 0.2, 0.6)}},
      {"triangle in the shared face",
       {Point<3>(0.1, 0.1, 0.),
        Point<3>(0.9, 0.1, 0.),
        Point<3>(0.1, 0.9, 0.)}},
      {"triangle through a tetrahedron edge",
       {Point<3>(-0.5, 0., 0.5),
        Point<3>(0.5, 0., -0.5),
        Point<3>(0., 1., 0.)}},
      {"triangle touching a vertex",
       {Point<3>(0., 0., 1.),
        Point<3>(0.5, 0.5, 1.5),
        Point<3>(-0.5, 0.5, 1.5)}}};
    for (const auto &[name, tri] : cases)
      {
        double energy = 0., area = 0., jump = 0.;
        bool   finite = true;
        for (const double shift : {1e-9, -1e-9})
          {
            Tri shifted = tri;
            for (auto &p : shifted)
              p[2] += shift;
            double shifted_energy = 0.;
            for (const auto &[tet, g] : tets)
              shifted_energy +=
                Contact::penalty_energy<double>(tet, shifted, g, 10.);
            energy = 0.;
            area   = 0.;
            for (const auto &[tet, g] : tets)
              {
                const auto d = penalty_ad(tet, tri, g, 10.);
                finite       = finite && std::isfinite(d.energy) &&
                         std::isfinite(d.gradient.l2_norm()) &&
                         std::isfinite(d.hessian.frobenius_norm());
                energy += d.energy;
                area += Contact::intersection_area(tet, tri);
              }
            jump = std::max(jump, std::abs(shifted_energy - energy));
          }
        deallog << name << ": area " << area << ", energy " << energy
                << ", all finite " << finite
                << ", energy change for a +-1e-9 shift "
                << error_bound(jump, -14) << std::endl;
      }
  }

  /**
   * Exactly degenerate pairs (a triangle vertex on a face, on an edge, at
   * a vertex of the tetrahedron; the triangle in a face plane) turned by a
   * random rotation about a random point, so that the degeneracy holds
   * only to rounding, as on a real mesh. The hand kernel's gradient
   * against central differences of the energy (step 1e-7) and against the
   * AD reference, on pairs with energy: the largest relative error, and
   * how many pairs are off by more than 1e-3.
   */
  void
  rotated_degenerate_families()
  {
    static const char *names[] = {"",
                                  "vertex on a face",
                                  "vertex on an edge",
                                  "vertex at a vertex",
                                  "triangle in a face plane"};
    deallog << "rotated exactly degenerate pairs, gradient of the hand kernel:"
            << std::endl;
    for (unsigned int kind = 1; kind < 5; ++kind)
      {
        unsigned int n = 0, n_off_fd = 0, n_off_ad = 0;
        double       e_fd = 0., e_ad = 0.;
        while (n < 200)
          {
            Tet            tet    = random_tet();
            Tri            tri    = triangle_near(tet, kind, 0.);
            const auto     g      = random_depths();
            const auto     Q      = random_rotation();
            const Point<3> center = random_point(1.);
            for (auto &p : tet)
              p = center + Q * (p - center);
            for (auto &p : tri)
              p = center + Q * (p - center);
            const auto c = coordinates(tet, tri);
            const auto h = hand_derivatives_of(c, g);
            // pairs with real energy: slivers of rounding size (a triangle
            // that only touches the tetrahedron) are left out
            const double scale =
              10. * 0.5 *
              cross_product_3d(tri[1] - tri[0], tri[2] - tri[0]).norm() *
              std::pow(*std::max_element(g.begin(), g.end()), 2);
            if (!(h.energy > 1e-8 * scale))
              continue;
            ++n;
            Vector<double> fd(21);
            for (unsigned int i = 0; i < 21; ++i)
              {
                auto         cp = c, cm = c;
                const double step = 1e-7;
                cp[i] += step;
                cm[i] -= step;
                fd[i] = (energy_of(cp, g) - energy_of(cm, g)) / (2. * step);
              }
            const auto     ad = derivatives_of(c, g);
            Vector<double> d(h.gradient);
            d -= fd;
            const double r_fd = d.l2_norm() / fd.l2_norm();
            d                 = h.gradient;
            d -= ad.gradient;
            const double r_ad = d.l2_norm() / ad.gradient.l2_norm();
            e_fd              = std::max(e_fd, r_fd);
            e_ad              = std::max(e_ad, r_ad);
            n_off_fd += r_fd > 1e-3;
            n_off_ad += r_ad > 1e-3;
          }
        // in a face plane the energy jumps (the triangle is in or out of
        // the tetrahedron): no finite difference across it means anything
        deallog << "  " << names[kind] << " (" << n << " pairs): ";
        if (kind < 4)
          deallog << "vs FD of the energy max " << scientific(e_fd)
                  << ", off by > 1e-3: " << n_off_fd << "; ";
        // the two differ by rounding only: a bound, not the last digits
        deallog << "vs AD " << error_bound(e_ad, -12)
                << ", off by > 1e-3: " << n_off_ad << std::endl;
      }
  }
} // namespace

int
main()
{
  initlog();
  area_against_sampling();
  derivatives_against_fd();
  hand_kernel_against_ad();
  collocation_against_ad();
  degenerate_positions();
  // last: it draws from the shared random generator
  rotated_degenerate_families();
}
