#include <tissue_contact/contact/point_collocation.h>

namespace TissueContact
{
  namespace Contact
  {
    PairDerivatives
    collocation_derivatives_ad(const std::array<Point<3>, 4> &tet,
                               const std::array<Point<3>, 3> &tri,
                               const std::array<double, 4>   &g,
                               const double                   eps_p,
                               const bool                     with_hessian)
    {
      return differentiate_pair(
        tet, tri, with_hessian, [&](const auto &tet_ad, const auto &tri_ad) {
          return collocation_energy(tet_ad, tri_ad, g, eps_p);
        });
    }
  } // namespace Contact
} // namespace TissueContact
