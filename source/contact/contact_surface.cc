#include <tissue_contact/contact/contact_parameters.h>
#include <tissue_contact/contact/contact_surface.h>

namespace TissueContact
{
  namespace Contact
  {
    ContactSurface::ContactSurface(
      const Discretization                                   &disc,
      const std::set<types::boundary_id>                     &contact_surfaces,
      const std::map<types::material_id, types::material_id> &body_of)
    {
      const auto body = [&](const types::material_id m) {
        return body_of_material(body_of, m);
      };
      const auto &tria = disc.dof_handler.get_triangulation();
      X                = tria.get_vertices();
      vertex_dofs.resize(X.size());
      for (const auto &cell : disc.dof_handler.active_cell_iterators())
        {
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int c = 0; c < 3; ++c)
              vertex_dofs[cell->vertex_index(v)][c] =
                cell->vertex_dof_index(v, c);
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() &&
                contact_surfaces.count(face->boundary_id()) > 0)
              {
                triangles.push_back({face->vertex_index(0),
                                     face->vertex_index(1),
                                     face->vertex_index(2)});
                const Tensor<1, 3> n =
                  cross_product_3d(face->vertex(1) - face->vertex(0),
                                   face->vertex(2) - face->vertex(0));
                outward.push_back(
                  n * (face->center() - cell->center()) > 0 ? 1 : -1);
                triangle_body.push_back(body(cell->material_id()));
              }
        }
    }


    std::vector<Point<3>>
    ContactSurface::positions(const Vector<double> &u) const
    {
      std::vector<Point<3>> x(X.size());
      for (unsigned int v = 0; v < X.size(); ++v)
        x[v] = position(v, u);
      return x;
    }


    void
    ContactSurface::vertex_areas_and_normals(
      const Vector<double>      &u,
      std::vector<double>       &area,
      std::vector<Tensor<1, 3>> &normal) const
    {
      area.assign(X.size(), 0.);
      normal.assign(X.size(), Tensor<1, 3>());
      for (unsigned int t = 0; t < triangles.size(); ++t)
        {
          const std::array<Point<3>, 3> x = triangle(t, u);
          const Tensor<1, 3>            a =
            0.5 * outward[t] * cross_product_3d(x[1] - x[0], x[2] - x[0]);
          for (const unsigned int v : triangles[t])
            {
              area[v] += a.norm() / 3.;
              normal[v] += a;
            }
        }
      for (auto &n : normal)
        if (n.norm() > 0.)
          n /= n.norm();
    }
  } // namespace Contact
} // namespace TissueContact
