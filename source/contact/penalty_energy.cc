#include <tissue_contact/base/multiversion.h>
#include <tissue_contact/contact/penalty_energy.h>


namespace TissueContact
{
  namespace Contact
  {
    TC_MULTIVERSION double
    penalty_energy_value(const std::array<Point<3>, 4> &tet,
                         const std::array<Point<3>, 3> &tri,
                         const std::array<double, 4>   &g,
                         const double                   eps_p)
    {
      return penalty_energy<double>(tet, tri, g, eps_p);
    }


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


  } // namespace Contact
} // namespace TissueContact
