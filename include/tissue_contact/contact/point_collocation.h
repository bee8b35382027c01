#pragma once

#include <tissue_contact/contact/penalty_energy.h>

namespace TissueContact
{
  namespace Contact
  {
    /**
     * The point-collocation baseline (dissertation 5.3.5, 6.5.1): the
     * penalty is sampled at the triangle's vertices only,
     * @f[ W = \frac{\varepsilon_p}{2}\sum_{k:\,x_k\in K}\frac{A_T}{3}\,
     *        g_h(x_k)^2 , @f]
     * with the depth @f$g_h@f$ interpolated in the tetrahedron K that
     * contains the vertex. Its force @f$\varepsilon_p A_T/3\; g\nabla g@f$
     * jumps when a vertex crosses into a tetrahedron with another depth
     * gradient: the chatter that area integration removes
     * (doc/theory/05-contact.md, sec. 8). Kept for comparison.
     */
    template <typename Number>
    Number
    collocation_energy(const std::array<Point<3, Number>, 4> &tet,
                       const std::array<Point<3, Number>, 3> &tri,
                       const std::array<double, 4>           &g,
                       const double                           eps_p)
    {
      using Traits = Differentiation::AD::ADNumberTraits<Number>;
      const Number area_third =
        cross_product_3d(tri[1] - tri[0], tri[2] - tri[0]).norm() / 6.;
      Number W(0.);
      for (unsigned int k = 0; k < 3; ++k)
        {
          // the vertex as a degenerate triangle: clipping keeps it iff it is
          // inside, with its barycentric coordinates
          const std::array<Point<3, Number>, 3> point = {tri[k],
                                                         tri[k],
                                                         tri[k]};
          const IntersectionPolygon<Number>     p     = intersect(tet, point);
          if (p.n_vertices == 0)
            continue;
          Number G(0.);
          for (unsigned int j = 0; j < 4; ++j)
            G += p.vertex[0].lambda[j] * g[j];
          if (Traits::get_scalar_value(G) > 0.)
            W += 0.5 * eps_p * area_third * G * G;
        }
      return W;
    }

  } // namespace Contact
} // namespace TissueContact
