#pragma once

#include <tissue_contact/base/discretization.h>
#include <tissue_contact/contact/body_contact_assembler.h>
#include <tissue_contact/contact/contact_interaction.h>
#include <tissue_contact/contact/contact_parameters.h>
#include <tissue_contact/contact/contact_surface.h>
#include <tissue_contact/contact/obstacle_assembler.h>

#include <memory>
#include <utility>
#include <vector>

namespace TissueContact
{
  namespace Contact
  {
    /**
     * All contact of a scene: its contact triangles (ContactSurface) and
     * the interactions its prm declares, the body pairs
     * (BodyContactAssembler, when any pair is declared) and the rigid
     * obstacles (ObstacleAssembler, when any obstacle is declared), each a
     * ContactInteraction. Contact enters the residual as
     * @f$R \mathrel{+}= \partial W/\partial u@f$ and the tangent as
     * @f$K \mathrel{+}= \partial^2 W/\partial u^2@f$, W the sum of their
     * penalty energies (doc/theory/05-contact.md).
     */
    class ContactAssembler : public ContactInteraction
    {
    public:
      /** The contact surfaces, obstacles and body pairs of @p parameters
       * on the space @p disc. */
      ContactAssembler(const Discretization &disc,
                       const Parameters     &parameters);

      void
      assemble(const Vector<double> &u,
               Vector<double>       &R,
               SparseMatrix<double> *K) const override;

      /** The penalty energy of each interaction at @p u: the body pairs in
       * their declared order, then the obstacles; energy() is the sum. */
      std::vector<double>
      energies(const Vector<double> &u) const override;

      void
      add_couplings(const Vector<double> &u,
                    const double          margin,
                    PatternRows          &rows,
                    const bool            where_missing = false) const override;

      bool
      has_couplings(const Vector<double>  &u,
                    const SparsityPattern &pattern) const override;

      /** The result of each interaction: the body pairs in their declared
       * order, then the obstacles (ContactInteraction::results()). */
      std::vector<ContactResult>
      results(const Vector<double>      &u,
              std::vector<Tensor<1, 3>> &surface_force,
              std::vector<double>       &penetration) const override;

      /**
       * What the output shows of contact at @p u, per mesh vertex
       * (doc/theory/05-contact.md, sec. 9): the contact traction
       * @f$t_a = f_a/A_a@f$ (the force @f$f_a@f$ the vertex receives as a
       * vertex of contact triangles over its tributary area @f$A_a@f$), the
       * contact pressure @f$p_a = -t_a\cdot n_a@f$ (positive in
       * compression, @f$n_a@f$ the outward normal) and the penetration,
       * the larger of the depth it reaches inside a paired body and inside
       * an obstacle; so @f$\sum_a t_a A_a@f$ is the total contact force on
       * the surface sides. With the results of every interaction.
       */
      struct SurfaceState
      {
        std::vector<ContactResult> interactions;
        std::vector<Tensor<1, 3>>  traction;
        std::vector<double>        pressure, penetration, area;
      };
      SurfaceState
      surface_state(const Vector<double> &u) const;

      /** The total penalty energy. */
      double
      energy(const Vector<double> &u) const;

      /** Time the body pairs' search, energies, sparsity check and
       * insertion in @p timer (null: not timed). */
      void
      set_timer(TimerOutput *timer) override;

      /** The contact triangles. */
      const ContactSurface &
      contact_surface() const
      {
        return surface;
      }

      /** Number of contact triangles. */
      unsigned int
      n_triangles() const
      {
        return surface.n_triangles();
      }

      /** BodyContactAssembler::n_tree_rebuilds() (0 without pairs). */
      unsigned int
      n_tree_rebuilds() const;

      /** BodyContactAssembler::vertex_depth() (empty without pairs). */
      const std::vector<double> &
      vertex_depth() const;

      /** BodyContactAssembler::max_penetration() (0 without pairs). */
      double
      max_body_penetration(const Vector<double> &u) const;

      /** BodyContactAssembler::penetrations() (empty without pairs). */
      std::vector<std::pair<unsigned int, double>>
      body_penetrations(const Vector<double> &u) const;

      /** BodyContactAssembler::pair_penetrations() (empty without
       * pairs). */
      std::vector<double>
      pair_penetrations(const Vector<double> &u) const;

      /** ObstacleAssembler::force() (zero without obstacles). */
      Tensor<1, 3>
      obstacle_force(const Vector<double> &u) const;

      /** The obstacles' augmented-Lagrangian multipliers
       * (ObstacleAssembler; nothing without obstacles). */
      ObstacleAssembler *
      obstacle_assembler()
      {
        return obstacles.get();
      }
      /** ObstacleAssembler::max_penetration() (0 without obstacles). */
      double
      max_obstacle_penetration(const Vector<double> &u) const;

    private:
      ContactSurface                        surface;
      std::unique_ptr<BodyContactAssembler> bodies;
      std::unique_ptr<ObstacleAssembler>    obstacles;
      /** bodies, then obstacles, where declared */
      std::vector<const ContactInteraction *> interactions;
    };
  } // namespace Contact
} // namespace TissueContact
