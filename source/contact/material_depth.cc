#include <tissue_contact/contact/bounding_volume_tree.h>
#include <tissue_contact/contact/contact_parameters.h>
#include <tissue_contact/contact/material_depth.h>

#include <deal.II/base/bounding_box.h>

#include <array>
#include <limits>
#include <map>

namespace TissueContact
{
  namespace Contact
  {
    double
    point_triangle_distance(const Point<3> &p,
                            const Point<3> &a,
                            const Point<3> &b,
                            const Point<3> &c)
    {
      // Voronoi regions of the triangle (closest point on a triangle, as in
      // C. Ericson, Real-Time Collision Detection, sec. 5.1.5)
      const Tensor<1, 3> ab = b - a, ac = c - a, ap = p - a;
      const double       d1 = ab * ap, d2 = ac * ap;
      if (d1 <= 0. && d2 <= 0.)
        return p.distance(a);
      const Tensor<1, 3> bp = p - b;
      const double       d3 = ab * bp, d4 = ac * bp;
      if (d3 >= 0. && d4 <= d3)
        return p.distance(b);
      const double vc = d1 * d4 - d3 * d2;
      if (vc <= 0. && d1 >= 0. && d3 <= 0.)
        return p.distance(a + d1 / (d1 - d3) * ab);
      const Tensor<1, 3> cp = p - c;
      const double       d5 = ab * cp, d6 = ac * cp;
      if (d6 >= 0. && d5 <= d6)
        return p.distance(c);
      const double vb = d5 * d2 - d1 * d6;
      if (vb <= 0. && d2 >= 0. && d6 <= 0.)
        return p.distance(a + d2 / (d2 - d6) * ac);
      const double va = d3 * d6 - d5 * d4;
      if (va <= 0. && (d4 - d3) >= 0. && (d5 - d6) >= 0.)
        return p.distance(b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b));
      const double denominator = 1. / (va + vb + vc);
      return p.distance(a + ab * (vb * denominator) + ac * (vc * denominator));
    }


    std::vector<double>
    compute_material_depth(
      const Triangulation<3>                                 &triangulation,
      const std::set<types::boundary_id>                     &contact_surfaces,
      const std::map<types::material_id, types::material_id> &body_of)
    {
      const auto body = [&](const types::material_id m) {
        return body_of_material(body_of, m);
      };
      using Triangle = std::array<Point<3>, 3>;
      std::map<types::material_id, std::vector<Triangle>> triangles;
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() &&
              contact_surfaces.count(face->boundary_id()) > 0)
            triangles[body(cell->material_id())].push_back(
              {face->vertex(0), face->vertex(1), face->vertex(2)});

      const auto         &vertices = triangulation.get_vertices();
      std::vector<double> depth(vertices.size(),
                                std::numeric_limits<double>::infinity());
      std::vector<bool>   done(vertices.size());
      for (const auto &[id, body_triangles] : triangles)
        {
          std::vector<BoundingBox<3>> boxes;
          boxes.reserve(body_triangles.size());
          for (const auto &t : body_triangles)
            boxes.emplace_back(std::vector<Point<3>>(t.begin(), t.end()));
          const BoundingVolumeTree tree(boxes);

          std::fill(done.begin(), done.end(), false);
          for (const auto &cell : triangulation.active_cell_iterators())
            if (body(cell->material_id()) == id)
              for (const unsigned int v : cell->vertex_indices())
                {
                  const unsigned int i = cell->vertex_index(v);
                  if (done[i])
                    continue;
                  done[i]           = true;
                  const Point<3> &p = vertices[i];
                  depth[i]          = std::min(
                    depth[i],
                    tree.nearest(p, [&](const unsigned int t, const double) {
                      const Triangle &tri = body_triangles[t];
                      return point_triangle_distance(p, tri[0], tri[1], tri[2]);
                    }));
                }
        }
      return depth;
    }
  } // namespace Contact
} // namespace TissueContact
