#include <tissue_contact/contact/analytic_obstacle.h>

namespace TissueContact
{
  namespace Contact
  {
    PairDerivatives
    obstacle_derivatives_ad(const AnalyticObstacle        &obstacle,
                            const std::array<Point<3>, 3> &tri,
                            const double                   eps_p,
                            const bool                     with_hessian)
    {
      std::vector<double> coordinates;
      for (const auto &p : tri)
        for (unsigned int d = 0; d < 3; ++d)
          coordinates.push_back(p[d]);
      const auto energy = [&](const auto &x) {
        using Number = typename std::decay_t<decltype(x)>::value_type;
        std::array<Point<3, Number>, 3> tri_ad;
        for (unsigned int v = 0; v < 3; ++v)
          for (unsigned int d = 0; d < 3; ++d)
            tri_ad[v][d] = x[3 * v + d];
        return obstacle_energy(obstacle, tri_ad, eps_p);
      };
      if (with_hessian)
        return differentiate(coordinates, energy);
      return differentiate_once(coordinates, energy);
    }
  } // namespace Contact
} // namespace TissueContact
