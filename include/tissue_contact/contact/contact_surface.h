#pragma once

#include <tissue_contact/base/discretization.h>

#include <deal.II/base/point.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <map>
#include <set>
#include <vector>

namespace TissueContact
{
  namespace Contact
  {
    using namespace dealii;

    /**
     * The contact triangles of a scene: the boundary faces whose boundary
     * id is a declared contact surface, with the material id of their cell,
     * and the vertices that carry the contact forces (the vertex DoFs of P1
     * or P2 elements). Every contact interaction works on it.
     */
    class ContactSurface
    {
    public:
      /** @p body_of: the body of each material id (Parameters::body_of). */
      ContactSurface(
        const Discretization               &disc,
        const std::set<types::boundary_id> &contact_surfaces,
        const std::map<types::material_id, types::material_id> &body_of = {});

      /** Number of contact triangles. */
      unsigned int
      n_triangles() const
      {
        return triangles.size();
      }

      /** Vertex indices of each contact triangle. */
      std::vector<std::array<unsigned int, 3>> triangles;
      /** The body of the cell each triangle bounds (its material id, or
       * the body several material ids form). */
      std::vector<types::material_id> triangle_body;
      /** +1 if the vertex order of a triangle turns its normal
       * @f$(x_1-x_0)\times(x_2-x_0)@f$ out of its cell, else -1. */
      std::vector<signed char> outward;
      /** Reference position of every vertex of the mesh. */
      std::vector<Point<3>> X;
      /** The three displacement DoFs of every vertex. */
      std::vector<std::array<types::global_dof_index, 3>> vertex_dofs;

      /** Current position of vertex @p v. */
      Point<3>
      position(const unsigned int v, const Vector<double> &u) const
      {
        return Point<3>(X[v][0] + u[vertex_dofs[v][0]],
                        X[v][1] + u[vertex_dofs[v][1]],
                        X[v][2] + u[vertex_dofs[v][2]]);
      }

      /** Current positions of all vertices. */
      std::vector<Point<3>>
      positions(const Vector<double> &u) const;

      /** At @p u, for every vertex of the mesh: its tributary contact area
       * @f$A_a@f$, a third of the current area of every contact triangle
       * it is a vertex of, and its outward unit normal @f$n_a@f$, the
       * normalized sum of those triangles' area vectors (both zero off
       * the contact surfaces). */
      void
      vertex_areas_and_normals(const Vector<double>      &u,
                               std::vector<double>       &area,
                               std::vector<Tensor<1, 3>> &normal) const;
      /** Current positions of the vertices of triangle @p t. */
      std::array<Point<3>, 3>
      triangle(const unsigned int t, const Vector<double> &u) const
      {
        return {position(triangles[t][0], u),
                position(triangles[t][1], u),
                position(triangles[t][2], u)};
      }
    };
  } // namespace Contact
} // namespace TissueContact
