#pragma once

#include <tissue_contact/contact/penalty_energy.h>

#include <deal.II/base/point.h>

#include <cmath>

namespace TissueContact
{
  namespace Contact
  {
    /**
     * A rigid obstacle with an analytic penetration depth d(x)
     * (dissertation 5.2; doc/theory/05-contact.md, sec. 6):
     * - a plane through @p point with unit normal @p normal pointing out of
     *   the obstacle (the bodies stay on that side):
     *   @f$d = -(x - p)\cdot n@f$;
     * - a sphere with @p center and @p radius (the bodies stay outside):
     *   @f$d = R - |x - c|@f$.
     * d > 0 inside the obstacle.
     */
    struct AnalyticObstacle
    {
      enum class Type
      {
        plane,
        sphere
      };
      Type         type = Type::plane;
      Point<3>     point;
      Tensor<1, 3> normal{{0., 0., 1.}};
      Point<3>     center;
      double       radius = 1.;

      template <typename Number>
      Number
      penetration(const Point<3, Number> &x) const
      {
        if (type == Type::plane)
          {
            Number d(0.);
            for (unsigned int i = 0; i < 3; ++i)
              d -= (x[i] - point[i]) * normal[i];
            return d;
          }
        Number r2(0.);
        for (unsigned int i = 0; i < 3; ++i)
          r2 += (x[i] - center[i]) * (x[i] - center[i]);
        return radius - std::sqrt(r2);
      }
    };

    /**
     * The part of a triangle @p tri where the linear interpolant of the
     * vertex values @p value is non-negative: the clipped polygon's
     * vertices @p x and their interpolated values @p d; returns their
     * number (0 if fewer than 3).
     */
    template <typename Number>
    unsigned int
    non_negative_part(const std::array<Point<3, Number>, 3> &tri,
                      const std::array<Number, 3>           &value,
                      std::array<Point<3, Number>, 4>       &x,
                      std::array<Number, 4>                 &d)
    {
      using Traits   = Differentiation::AD::ADNumberTraits<Number>;
      unsigned int n = 0;
      for (unsigned int k = 0; k < 3; ++k)
        {
          const Point<3, Number> &p = tri[k], &q = tri[(k + 1) % 3];
          const Number           &dp = value[k], &dq = value[(k + 1) % 3];
          const bool              p_in = Traits::get_scalar_value(dp) >= 0.;
          const bool              q_in = Traits::get_scalar_value(dq) >= 0.;
          if (p_in)
            {
              x[n]   = p;
              d[n++] = dp;
            }
          if (p_in != q_in)
            {
              const Number t = dp / (dp - dq);
              x[n]           = p + t * (q - p);
              d[n++]         = Number(0.);
            }
        }
      return n < 3 ? 0 : n;
    }

    /**
     * The part of a boundary triangle on the obstacle's side, where the
     * linear interpolant @f$d_h@f$ of the vertex penetrations is
     * non-negative (non_negative_part() of the penetrations).
     */
    template <typename Number>
    unsigned int
    penetrating_part(const AnalyticObstacle                &obstacle,
                     const std::array<Point<3, Number>, 3> &tri,
                     std::array<Point<3, Number>, 4>       &x,
                     std::array<Number, 4>                 &d)
    {
      return non_negative_part(tri,
                               {{obstacle.penetration(tri[0]),
                                 obstacle.penetration(tri[1]),
                                 obstacle.penetration(tri[2])}},
                               x,
                               d);
    }

    /**
     * The penalty energy of a boundary triangle against an obstacle,
     * @f$W = \frac{\varepsilon_p}{2}\int_{T,\,d_h>0} d_h^2\,da@f$, with
     * @f$d_h@f$ the linear interpolant of the vertex penetrations (exact for
     * the plane, second-order accurate for the sphere): the triangle is
     * clipped by @f$d_h \ge 0@f$ (penetrating_part()) and
     * integral_of_square() integrates.
     */
    template <typename Number>
    Number
    obstacle_energy(const AnalyticObstacle                &obstacle,
                    const std::array<Point<3, Number>, 3> &tri,
                    const double                           eps_p)
    {
      std::array<Point<3, Number>, 4> x;
      std::array<Number, 4>           d;
      const unsigned int              n = penetrating_part(obstacle, tri, x, d);
      if (n == 0)
        return Number(0.);
      return 0.5 * eps_p * integral_of_square(x, d, n, unit_normal(tri));
    }

    /**
     * The augmented-Lagrangian energy of a boundary triangle against an
     * obstacle (doc/theory/05-contact.md, sec. 6.1), with the vertex
     * multipliers @p lambda held fixed:
     * @f$W = \frac{\varepsilon_p}{2}\int_{T,\,\varphi_h>0}\varphi_h^2\,da
     *      - \frac{1}{2\varepsilon_p}\int_T \lambda_h^2\,da@f$ with
     * @f$\varphi = d + \lambda/\varepsilon_p@f$, the interpolants linear
     * over the triangle. Where @f$\varphi_h > 0@f$ on all of T the
     * integrand is @f$\lambda_h d_h + \frac{\varepsilon_p}{2}d_h^2@f$:
     * the pressure @f$\lambda + \varepsilon_p d@f$. With @p lambda zero it
     * is obstacle_energy(). @f$C^1@f$ in the positions: the penalty's kink
     * moves from @f$d = 0@f$ to @f$d = -\lambda/\varepsilon_p@f$.
     */
    template <typename Number>
    Number
    augmented_obstacle_energy(const AnalyticObstacle                &obstacle,
                              const std::array<Point<3, Number>, 3> &tri,
                              const double                           eps_p,
                              const std::array<double, 3>           &lambda)
    {
      std::array<Number, 3> phi;
      for (unsigned int k = 0; k < 3; ++k)
        phi[k] = obstacle.penetration(tri[k]) + lambda[k] / eps_p;
      std::array<Point<3, Number>, 4> x;
      std::array<Number, 4>           v;
      const unsigned int              n = non_negative_part(tri, phi, x, v);
      Number                          W(0.);
      if (n > 0)
        W = 0.5 * eps_p * integral_of_square(x, v, n, unit_normal(tri));
      const Tensor<1, 3, Number> a =
        cross_product_3d(tri[1] - tri[0], tri[2] - tri[0]);
      const Number area = 0.5 * std::sqrt(a * a);
      const double l1   = lambda[0] + lambda[1] + lambda[2];
      const double l2 =
        lambda[0] * lambda[0] + lambda[1] * lambda[1] + lambda[2] * lambda[2];
      return W - area / (24. * eps_p) * (l2 + l1 * l1);
    }

    /** The area of the planar polygon of the first @p n vertices of
     * @p x (a fan from the first). */
    inline double
    polygon_area(const std::array<Point<3>, 4> &x, const unsigned int n)
    {
      double area = 0.;
      for (unsigned int k = 1; k + 1 < n; ++k)
        area += 0.5 * cross_product_3d(x[k] - x[0], x[k + 1] - x[0]).norm();
      return area;
    }

    /** The area of penetrating_part(): where the penalty of
     * obstacle_energy() acts. */
    inline double
    obstacle_contact_area(const AnalyticObstacle        &obstacle,
                          const std::array<Point<3>, 3> &tri)
    {
      std::array<Point<3>, 4> x;
      std::array<double, 4>   d;
      return polygon_area(x, penetrating_part(obstacle, tri, x, d));
    }

  } // namespace Contact
} // namespace TissueContact
