#pragma once

#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <map>
#include <set>
#include <vector>

namespace TissueContact
{
  namespace Contact
  {
    using namespace dealii;

    /** Exact Euclidean distance from @p p to the triangle (a, b, c):
     * to its interior, an edge or a vertex, whichever is nearest. */
    double
    point_triangle_distance(const Point<3> &p,
                            const Point<3> &a,
                            const Point<3> &b,
                            const Point<3> &c);

    /**
     * The material depth of dissertation sec. 5.4.1 at every vertex: the
     * distance, in the reference configuration, from the vertex to the
     * contact boundary of its body — the boundary faces whose boundary id
     * is in @p contact_surfaces, of cells with the same material id. It is
     * zero on the contact boundary and grows inwards; inside a tetrahedron
     * it is interpolated linearly from the four vertices
     * (doc/theory/05-contact.md, sec. 1). A vertex shared by several bodies
     * takes the smallest of their depths; a vertex of a body without a
     * contact surface gets +infinity. A body is a material id, or the
     * material ids that @p body_of maps to the same body id (a body of
     * several materials: its depth is measured to its whole contact
     * boundary, across the interfaces of its materials).
     *
     * Each body's contact triangles go into a BoundingVolumeTree and every
     * vertex queries its nearest triangle by branch and bound: about
     * O(N log M) for N vertices and M triangles, instead of O(N M).
     */
    std::vector<double>
    compute_material_depth(
      const Triangulation<3>                                 &triangulation,
      const std::set<types::boundary_id>                     &contact_surfaces,
      const std::map<types::material_id, types::material_id> &body_of = {});
  } // namespace Contact
} // namespace TissueContact
