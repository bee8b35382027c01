#pragma once

#include <array>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <set>
#include <tissue_contact/contact/analytic_obstacle.h>
#include <tissue_contact/elasticity/discretization.h>
#include <vector>

namespace TissueContact
{
  namespace Contact
  {
    /** A rigid obstacle, its penalty factor and the bodies (material ids;
     * empty: all) whose contact triangles it pushes. */
    struct ObstacleContact
    {
      AnalyticObstacle             obstacle;
      double                       penalty = 1.;
      std::set<types::material_id> bodies;
    };

    /**
     * Adds the penalty contact forces and their exact tangent to the
     * residual and the matrix of the elastic problem. The contact
     * triangles are the boundary faces whose boundary id is a declared
     * contact surface; their vertices (the vertex DoFs of P1 or P2
     * elements) carry the forces. Contact enters the residual as
     * @f$R \mathrel{+}= \partial W/\partial u@f$ and the tangent as
     * @f$K \mathrel{+}= \partial^2 W/\partial u^2@f$, W the total penalty
     * energy (doc/theory/05-contact.md). A triangle is differentiated only
     * if one of its vertices penetrates (cheap rejection).
     */
    class ContactAssembler
    {
    public:
      ContactAssembler(const Elasticity::Discretization   &disc,
                       const std::set<types::boundary_id> &contact_surfaces,
                       const std::vector<ObstacleContact> &obstacles);

      /** Add the contact residual and, if @p K is not null, tangent. */
      void
      assemble(const Vector<double> &u,
               Vector<double>       &R,
               SparseMatrix<double> *K) const;

      /** The total penalty energy. */
      double
      energy(const Vector<double> &u) const;

      /** Total force the obstacles exert on the bodies,
       * @f$-\sum_a \partial W/\partial x_a@f$. */
      Tensor<1, 3>
      obstacle_force(const Vector<double> &u) const;

      /** Largest penetration of a contact vertex into an obstacle. */
      double
      max_obstacle_penetration(const Vector<double> &u) const;

      /** Number of contact triangles. */
      unsigned int
      n_triangles() const
      {
        return triangles.size();
      }

    private:
      std::vector<std::array<unsigned int, 3>> triangles; // vertex indices
      std::vector<types::material_id>          triangle_body;
      std::vector<ObstacleContact>             obstacles;
      std::vector<Point<3>>                    X; // reference positions
      std::vector<std::array<types::global_dof_index, 3>> vertex_dofs;

      Point<3>
      position(const unsigned int v, const Vector<double> &u) const;

      /** Call @p f(triangle, obstacle, derivatives) for every triangle and
       * obstacle in contact. */
      template <typename F>
      void
      for_each_obstacle_contact(const Vector<double> &u, const F &f) const;
    };
  } // namespace Contact
} // namespace TissueContact
