#pragma once

#include <tissue_contact/base/discretization.h>
#include <tissue_contact/contact/analytic_obstacle.h>
#include <tissue_contact/contact/bounding_volume_tree.h>
#include <tissue_contact/contact/contact_parameters.h>
#include <tissue_contact/contact/penalty_kernel.h>
#include <tissue_contact/contact/point_collocation.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <memory>
#include <set>
#include <vector>

namespace TissueContact
{
  namespace Contact
  {
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
      /** The contact surfaces, obstacles and body pairs of @p parameters
       * on the space @p disc. */
      ContactAssembler(const Discretization &disc,
                       const Parameters     &parameters);

      /** Add to @p dsp the DoF couplings of every (triangle, tetrahedron)
       * candidate of the body pairs at @p u whose boxes overlap after the
       * triangle's box is enlarged by @p margin. */
      void
      add_couplings(const Vector<double>   &u,
                    const double            margin,
                    DynamicSparsityPattern &dsp) const;

      /** Whether @p pattern holds the couplings of every candidate pair at
       * @p u (else the matrix pattern must grow before assembly). */
      bool
      has_couplings(const Vector<double>  &u,
                    const SparsityPattern &pattern) const;

      /** How often the tree was rebuilt (a vertex moved farther than the
       * mean tetrahedron size since the last build). */
      unsigned int
      n_tree_rebuilds() const
      {
        return n_rebuilds;
      }

      /** Material depth at every vertex. */
      const std::vector<double> &
      vertex_depth() const
      {
        return depth;
      }

      /** Largest material depth reached by a vertex of a contact triangle
       * inside a tetrahedron of a paired body (the penetration). */
      double
      max_body_penetration(const Vector<double> &u) const;

      /** For every vertex of a contact triangle of a paired surface body:
       * (its vertex index, the material depth it reaches inside a paired
       * body, zero if none). With the area-integrated penalty the contact
       * pressure at a surface point is @f$\varepsilon_p@f$ times this depth
       * (per direction of a pair). */
      std::vector<std::pair<unsigned int, double>>
      body_penetrations(const Vector<double> &u) const;

      /** Add the contact residual and, if @p K is not null, tangent. */
      void
      assemble(const Vector<double> &u,
               Vector<double>       &R,
               SparseMatrix<double> *K) const;

      /** The total penalty energy. */
      double
      energy(const Vector<double> &u) const;

      /** The penalty energy of each interaction at @p u: the body pairs in
       * their declared order, then the obstacles; energy() is the sum. */
      std::vector<double>
      energies(const Vector<double> &u) const;

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

      std::vector<BodyContact>                    pairs;
      std::vector<double>                         depth; // per vertex
      std::vector<std::array<unsigned int, 4>>    tets;  // vertex indices
      std::vector<types::material_id>             tet_body;
      mutable std::unique_ptr<BoundingVolumeTree> tree; // over tets
      mutable unsigned int                        n_rebuilds = 0;
      mutable std::vector<Point<3>> x_at_build; // positions at the build
      double rebuild_distance = 0.;             // mean tetrahedron box diagonal

      /** Refit the tree to the positions @p x of the vertices. */
      void
      refit(const std::vector<Point<3>> &x) const;

      /** Call @p f(t, k, pair) for every candidate pair of triangle t and
       * tetrahedron k of a body pair (boxes overlapping after enlarging
       * the triangle's by @p margin), triangles that are faces of the
       * tetrahedron excluded. */
      template <typename F>
      void
      for_each_candidate(const std::vector<Point<3>> &x,
                         const double                 margin,
                         const F                     &f) const;
      /** for_each_candidate() for one triangle @p t. */
      template <typename F>
      void
      for_each_candidate_of(const unsigned int           t,
                            const std::vector<Point<3>> &x,
                            const double                 margin,
                            const F                     &f) const;
      /** Whether triangle @p t belongs to the surface body of a pair. */
      bool
      surface_of_a_pair(const unsigned int t) const;
      /** The positions and depths of triangle t and tetrahedron k. */
      struct PairGeometry
      {
        std::array<Point<3>, 4> tet;
        std::array<Point<3>, 3> tri;
        std::array<double, 4>   g;
      };
      PairGeometry
      pair_geometry(const std::vector<Point<3>> &x,
                    const unsigned int           t,
                    const unsigned int           k) const;


      std::array<types::global_dof_index, 21>
      pair_dofs(const unsigned int t, const unsigned int k) const;

      /** Current positions of all vertices. */
      std::vector<Point<3>>
      positions(const Vector<double> &u) const;

      /** Call @p f(t, k, derivatives) for every intersecting pair of a
       * contact triangle t and a tetrahedron k with nonzero energy. */
      template <typename F>
      void
      for_each_pair_contact(const Vector<double> &u,
                            const bool            with_hessian,
                            const F              &f) const;

      Point<3>
      position(const unsigned int v, const Vector<double> &u) const;

      /** Call @p f(triangle, obstacle, derivatives) for every triangle and
       * obstacle in contact. */
      template <typename F>
      void
      for_each_obstacle_contact(const Vector<double> &u,
                                const bool            with_hessian,
                                const F              &f) const;
    };
  } // namespace Contact
} // namespace TissueContact
