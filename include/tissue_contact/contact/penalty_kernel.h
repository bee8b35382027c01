#pragma once

#include <tissue_contact/contact/triangle_tetrahedron_intersection.h>

#include <array>

namespace TissueContact
{
  namespace Contact
  {
    /**
     * Energy, gradient and Hessian of one triangle-tetrahedron pair with
     * respect to its 21 coordinates (the 4 tetrahedron vertices, then the 3
     * triangle vertices, x y z each), in fixed-size storage: no allocation
     * per pair.
     */
    struct PairKernel
    {
      static constexpr unsigned int n_coordinates = 21;

      double                                 energy = 0.;
      std::array<double, 21>                 gradient;
      std::array<std::array<double, 21>, 21> hessian;
    };

    /**
     * The penalty energy of a pair (penalty_energy.h) with its exact
     * gradient and, if @p with_hessian, its exact Hessian, derived by hand
     * (doc/theory/05-contact.md, sec. 5.1): the energy is @f$W = c N
     * \Phi(\Lambda)@f$, N twice the triangle's area and @f$\Lambda_{jt}@f$
     * the tetrahedron's barycentric coordinates of the triangle's vertices;
     * every polygon vertex is, by its clipping labels, a triangle vertex, a
     * triangle edge cut by a face plane or a tetrahedron edge cut by the
     * triangle's plane, a closed form in the triangle's barycentric
     * coordinates; the fan integral is differentiated in those, chained to
     * @f$\Lambda@f$ and from there to the 21 coordinates.
     *
     * Returns false (and leaves @p result unset) when the energy is zero.
     * The automatic-differentiation reference (ad_derivatives() of
     * penalty_energy(), contact/ad_reference.h) computes the same numbers;
     * the test contact/penalty_kernel compares them.
     */
    bool
    penalty_kernel(const std::array<Point<3>, 4> &tet,
                   const std::array<Point<3>, 3> &tri,
                   const std::array<double, 4>   &g,
                   const double                   eps_p,
                   const bool                     with_hessian,
                   PairKernel                    &result);

    /**
     * The point-collocation energy (point_collocation.h) with its exact
     * gradient and Hessian, derived by hand:
     * @f$W = c\,A_T\sum_k G_k^2@f$ over the triangle vertices inside the
     * tetrahedron with positive depth, @f$c = \varepsilon_p/6@f$,
     * @f$G_k = N_k/V@f$ as in penalty_kernel(). Tested against
     * ad_derivatives() of collocation_energy(). Returns false when the energy
     * is zero.
     */
    bool
    collocation_kernel(const std::array<Point<3>, 4> &tet,
                       const std::array<Point<3>, 3> &tri,
                       const std::array<double, 4>   &g,
                       const double                   eps_p,
                       const bool                     with_hessian,
                       PairKernel                    &result);
  } // namespace Contact
} // namespace TissueContact
