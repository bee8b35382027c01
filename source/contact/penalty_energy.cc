#include <deal.II/differentiation/ad.h>
#include <tissue_contact/contact/penalty_energy.h>

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


    PairDerivatives
    penalty_derivatives_ad(const std::array<Point<3>, 4> &tet,
                           const std::array<Point<3>, 3> &tri,
                           const std::array<double, 4>   &g,
                           const double                   eps_p)
    {
      using ADHelper = Differentiation::AD::ScalarFunction<
        3,
        Differentiation::AD::NumberTypes::sacado_dfad_dfad,
        double>;
      using ADNumber = ADHelper::ad_type;

      std::vector<double> coordinates(21);
      for (unsigned int v = 0; v < 4; ++v)
        for (unsigned int d = 0; d < 3; ++d)
          coordinates[3 * v + d] = tet[v][d];
      for (unsigned int v = 0; v < 3; ++v)
        for (unsigned int d = 0; d < 3; ++d)
          coordinates[12 + 3 * v + d] = tri[v][d];

      ADHelper ad(21);
      ad.register_independent_variables(coordinates);
      const std::vector<ADNumber> x = ad.get_sensitive_variables();

      std::array<Point<3, ADNumber>, 4> tet_ad;
      std::array<Point<3, ADNumber>, 3> tri_ad;
      for (unsigned int v = 0; v < 4; ++v)
        for (unsigned int d = 0; d < 3; ++d)
          tet_ad[v][d] = x[3 * v + d];
      for (unsigned int v = 0; v < 3; ++v)
        for (unsigned int d = 0; d < 3; ++d)
          tri_ad[v][d] = x[12 + 3 * v + d];

      ad.register_dependent_variable(penalty_energy(tet_ad, tri_ad, g, eps_p));

      PairDerivatives result;
      result.energy = ad.compute_value();
      result.gradient.reinit(21);
      ad.compute_gradient(result.gradient);
      result.hessian.reinit(21, 21);
      ad.compute_hessian(result.hessian);
      return result;
    }
  } // namespace Contact
} // namespace TissueContact
