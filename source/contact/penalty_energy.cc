#include <tissue_contact/contact/penalty_energy.h>

#include <deal.II/differentiation/ad.h>

namespace TissueContact
{
  namespace Contact
  {
    double
    intersection_area(const std::array<Point<3>, 4> &tet,
                      const std::array<Point<3>, 3> &tri)
    {
      const IntersectionPolygon<double> polygon = intersect(tet, tri);
      double                            area    = 0.;
      for (unsigned int k = 1; k + 1 < polygon.n_vertices; ++k)
        area +=
          0.5 * cross_product_3d(polygon.vertex[k].x - polygon.vertex[0].x,
                                 polygon.vertex[k + 1].x - polygon.vertex[0].x)
                  .norm();
      return area;
    }


    namespace
    {
      /** The AD driver of differentiate() and differentiate_once(). */
      template <Differentiation::AD::NumberTypes code, typename Energy>
      PairDerivatives
      run_ad(const std::vector<double> &coordinates,
             const Energy              &energy,
             const bool                 with_hessian)
      {
        using ADHelper = Differentiation::AD::ScalarFunction<3, code, double>;
        const unsigned int n = coordinates.size();
        ADHelper           ad(n);
        ad.register_independent_variables(coordinates);
        ad.register_dependent_variable(energy(ad.get_sensitive_variables()));
        PairDerivatives result;
        result.energy = ad.compute_value();
        result.gradient.reinit(n);
        ad.compute_gradient(result.gradient);
        if (with_hessian)
          {
            result.hessian.reinit(n, n);
            ad.compute_hessian(result.hessian);
          }
        return result;
      }
    } // namespace


    PairDerivatives
    differentiate(
      const std::vector<double>                                    &coordinates,
      const std::function<ADNumber(const std::vector<ADNumber> &)> &energy)
    {
      return run_ad<Differentiation::AD::NumberTypes::sacado_dfad_dfad>(
        coordinates, energy, true);
    }


    PairDerivatives
    differentiate_once(
      const std::vector<double> &coordinates,
      const std::function<ADNumber1(const std::vector<ADNumber1> &)> &energy)
    {
      return run_ad<Differentiation::AD::NumberTypes::sacado_dfad>(coordinates,
                                                                   energy,
                                                                   false);
    }


    PairDerivatives
    penalty_derivatives_ad(const std::array<Point<3>, 4> &tet,
                           const std::array<Point<3>, 3> &tri,
                           const std::array<double, 4>   &g,
                           const double                   eps_p,
                           const bool                     with_hessian)
    {
      return differentiate_pair(
        tet, tri, with_hessian, [&](const auto &tet_ad, const auto &tri_ad) {
          return penalty_energy(tet_ad, tri_ad, g, eps_p);
        });
    }
  } // namespace Contact
} // namespace TissueContact
