#pragma once

#include <deal.II/base/timer.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
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

      /** Add to @p dsp the couplings the tangent may have at @p u (with a
       * search margin @p margin); none by default. */
      virtual void
      add_couplings(const Vector<double>   &u,
                    const double            margin,
                    DynamicSparsityPattern &dsp) const
      {
        (void)u;
        (void)margin;
        (void)dsp;
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
