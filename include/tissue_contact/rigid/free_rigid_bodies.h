#pragma once

#include <tissue_contact/base/pattern_rows.h>
#include <tissue_contact/rigid/rotation.h>

#include <deal.II/base/point.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <string>
#include <vector>

namespace TissueContact
{
  namespace Rigid
  {
    using namespace dealii;

    /**
     * Rigid bodies whose motion is unknown (doc/theory/07), FEBio's rigid
     * bodies: each has six unknowns q = (t, theta), the displacement t of its
     * center c (the mean of its support points) and a rotation vector theta,
     * appended after the n_fe finite element DoFs. Every DoF s of the body
     * (component i of the support point X) is a slave,
     * @f[ u_s(q) = \big(R(\theta)(X - c) + c + t - X\big)_i, @f]
     * nonlinear in q. The finite element residual and tangent are assembled
     * over all n_fe DoFs as if the slaves were free; condense() then turns
     * them into the residual and tangent in the independent unknowns:
     * @f$R_q = \sum_s J_s^T R_s@f$, @f$K \leftarrow T^T K T + \sum_s R_s
     * \partial^2 u_s/\partial q^2@f$ with @f$T = \partial u/\partial
     * (u_{free}, q)@f$, and each slave row and column becomes an identity
     * row (its residual zero), so every solver sees a square system whose
     * slave entries stay where they are; expand() gives the displacement
     * of all n_fe DoFs.
     */
    class FreeRigidBodies
    {
    public:
      /** One body: a name and the DoFs of its cells, with their component
       * and the reference position of their support point. */
      struct Body
      {
        std::string                          name;
        std::vector<types::global_dof_index> dofs;
        std::vector<unsigned int>            components;
        std::vector<Point<3>>                X;
      };

      /** The bodies @p bodies of a finite element space of @p n_fe DoFs;
       * their unknowns are n_fe + 6 b ... n_fe + 6 b + 5. A DoF in two of
       * them is an error naming both. */
      FreeRigidBodies(const types::global_dof_index n_fe,
                      const std::vector<Body>      &bodies);

      /** Number of bodies. */
      unsigned int
      n_bodies() const
      {
        return bodies.size();
      }
      /** Number of unknowns: n_fe + 6 n_bodies(). */
      types::global_dof_index
      n_dofs() const
      {
        return n_fe + 6 * bodies.size();
      }
      /** Index of the first of body @p b's six unknowns (t, then theta). */
      types::global_dof_index
      first_unknown(const unsigned int b) const
      {
        return n_fe + 6 * b;
      }
      const std::string &
      name(const unsigned int b) const
      {
        return bodies[b].name;
      }
      /** The center c of body @p b (reference configuration). */
      const Point<3> &
      center(const unsigned int b) const
      {
        return centers[b];
      }
      /** Whether finite element DoF @p i is a slave of a body. */
      bool
      is_slave(const types::global_dof_index i) const
      {
        return owner[i] >= 0;
      }
      /** The translation t of body @p b in the unknowns @p u. */
      Tensor<1, 3>
      translation(const Vector<double> &u, const unsigned int b) const;
      /** The rotation vector theta of body @p b in @p u. */
      Tensor<1, 3>
      rotation_vector(const Vector<double> &u, const unsigned int b) const;

      /** @p u_fe (n_fe entries) = the first n_fe entries of @p u (n_dofs()),
       * with every slave set to u_s(q). */
      void
      expand(const Vector<double> &u, Vector<double> &u_fe) const;

      /** Set the slave entries of @p u (n_dofs()) to u_s(q). */
      void
      complete(Vector<double> &u) const;

      /**
       * From the finite element residual @p R_fe (n_fe) at expand(u) to the
       * residual @p R (n_dofs()) in the independent unknowns, and, if @p K
       * is not null, the tangent assembled into its first n_fe rows and
       * columns to the tangent in them (in place).
       */
      void
      condense(const Vector<double> &u,
               const Vector<double> &R_fe,
               Vector<double>       &R,
               SparseMatrix<double> *K) const;

      /** @p rows, the n_fe rows of the finite element pattern, extended to
       * the n_dofs() rows of the condensed tangent: the couplings of every
       * body's unknowns with each other and with every DoF coupled to one
       * of its slaves added. */
      void
      add_couplings(PatternRows &rows) const;

      /** A diagonal D_fe over the n_fe DoFs (the quasi-viscosity) as a
       * diagonal over n_dofs(): zero on slaves, diag(T^T D T) at q = 0 on
       * the bodies' unknowns. */
      Vector<double>
      condense_diagonal(const Vector<double> &D_fe) const;


    private:
      /** d u_s / d q of every slave of body @p b at the rotation @p rot (one row of six
       * per slave, in the order of Body::dofs). */
      std::vector<std::array<double, 6>>
      jacobian(const unsigned int b, const RotationDerivatives &rot) const;

      const types::global_dof_index n_fe;
      std::vector<Body>             bodies;
      std::vector<Point<3>>         centers;
      /** Per finite element DoF: its body, or -1. */
      std::vector<int> owner;
      /** Per finite element DoF: its index in its body's Body::dofs. */
      std::vector<unsigned int> slave_index;
      /** Per body: its slaves' DoFs in increasing order. */
      std::vector<std::vector<types::global_dof_index>> slaves;
    };
  } // namespace Rigid
} // namespace TissueContact
