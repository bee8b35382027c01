#pragma once

#include <tissue_contact/base/pattern_rows.h>

#include <deal.II/base/tensor.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace TissueContact
{
  namespace Contact
  {
    using namespace dealii;

    /**
     * What one declared interaction (a body pair or an obstacle) transmits
     * at a state (doc/theory/05-contact.md, sec. 9): the contact force on
     * its surface side, @f$F = -\sum_{a} \partial W/\partial x_a@f$ over the
     * vertices of its contact triangles (for a body pair the volume body
     * receives @f$-F@f$; for self-contact F is the force the triangles
     * receive from the body they enter), the contact area (the part of the
     * contact triangles where the penalty acts: inside the volume body, or
     * on the obstacle's side of its surface), the largest penetration and
     * the penalty energy.
     */
    struct ContactResult
    {
      Tensor<1, 3> force;
      double       area            = 0.;
      double       max_penetration = 0.;
      double       energy          = 0.;
    };

    /**
     * What the problem needs of one kind of contact (doc/theory/05-contact.md,
     * sec. 7): its penalty energy W, added to the residual as
     * @f$R \mathrel{+}= \partial W/\partial u@f$ and to the tangent as
     * @f$K \mathrel{+}= \partial^2 W/\partial u^2@f$, the energy of each
     * declared interaction, and the matrix couplings it creates between
     * DoFs of different elements. The kinds: BodyContactAssembler (body
     * pairs and self-contact by material depth), ObstacleAssembler (rigid
     * analytic obstacles).
     */
    class ContactInteraction
    {
    public:
      virtual ~ContactInteraction() = default;

      /** Add the contact residual and, if @p K is not null, tangent. */
      virtual void
      assemble(const Vector<double> &u,
               Vector<double>       &R,
               SparseMatrix<double> *K) const = 0;

      /** The penalty energy of each declared interaction at @p u. */
      virtual std::vector<double>
      energies(const Vector<double> &u) const = 0;

      /** The result of each declared interaction at @p u (in the order of
       * energies()); per mesh vertex (the vectors sized by the caller), the
       * contact force each vertex of a contact triangle receives as a
       * triangle vertex added to @p surface_force, and the penetration it
       * reaches raised to it in @p penetration. */
      virtual std::vector<ContactResult>
      results(const Vector<double>      &u,
              std::vector<Tensor<1, 3>> &surface_force,
              std::vector<double>       &penetration) const = 0;

      /** Add to @p rows (one per DoF) the couplings the tangent may have at
       * @p u (with a search margin @p margin); none by default. With
       * @p where_missing, @p rows already hold the pattern that the last
       * has_couplings(), at the same @p u, found incomplete, and only the
       * couplings near what it found missing need adding. */
      virtual void
      add_couplings(const Vector<double> &u,
                    const double          margin,
                    PatternRows          &rows,
                    const bool            where_missing = false) const
      {
        (void)u;
        (void)margin;
        (void)rows;
        (void)where_missing;
      }

      /** Whether @p pattern holds every coupling the tangent has at @p u. */
      virtual bool
      has_couplings(const Vector<double>  &u,
                    const SparsityPattern &pattern) const
      {
        (void)u;
        (void)pattern;
        return true;
      }

      /** Time the contact search, the line search's energies, the
       * sparsity check and the matrix insertion in sections of @p timer
       * named "contact: ..." (null: not timed). */
      virtual void
      set_timer(TimerOutput *timer)
      {
        this->timer = timer;
      }

    protected:
      TimerOutput *timer = nullptr;
    };
  } // namespace Contact
} // namespace TissueContact
