#pragma once

#include <tissue_contact/contact/ad_reference.h>
#include <tissue_contact/contact/contact_interaction.h>
#include <tissue_contact/contact/contact_parameters.h>
#include <tissue_contact/contact/contact_surface.h>

#include <deal.II/base/tensor.h>

#include <array>
#include <deque>
#include <vector>

namespace TissueContact
{
  namespace Contact
  {
    /**
     * Contact of the contact triangles with rigid analytic obstacles
     * (planes, spheres; doc/theory/05-contact.md, sec. 6): the penalty
     * @f$W = \frac{\varepsilon_p}{2}\int d_h^2\,da@f$ over the penetrating
     * part of every triangle of the bodies an obstacle pushes, its exact
     * gradient and Hessian in the 9 vertex coordinates by automatic
     * differentiation. A triangle none of whose vertices penetrates is
     * skipped. Couples only DoFs of one face: no pattern change.
     */
    class ObstacleAssembler : public ContactInteraction
    {
    public:
      ObstacleAssembler(const ContactSurface               &surface,
                        const std::vector<ObstacleContact> &obstacles);

      void
      assemble(const Vector<double> &u,
               Vector<double>       &R,
               SparseMatrix<double> *K) const override;

      /** One energy per obstacle, in the declared order. */
      std::vector<double>
      energies(const Vector<double> &u) const override;

      /** Per obstacle: the force on the bodies it pushes, the area of
       * their triangles' penetrating parts (obstacle_contact_area()), the
       * largest vertex penetration and the energy. */
      std::vector<ContactResult>
      results(const Vector<double>      &u,
              std::vector<Tensor<1, 3>> &surface_force,
              std::vector<double>       &penetration) const override;

      /** Total force the obstacles exert on the bodies,
       * @f$-\sum_a \partial W/\partial x_a@f$. */
      Tensor<1, 3>
      force(const Vector<double> &u) const;

      /** Per mesh vertex: the largest penetration into an obstacle that
       * pushes a contact triangle of the vertex (0 elsewhere). */
      std::vector<double>
      vertex_penetrations(const Vector<double> &u) const;

      /** Largest penetration of a contact vertex into an obstacle. */
      double
      max_penetration(const Vector<double> &u) const;

      /**
       * The augmented-Lagrangian (Uzawa) update (doc/theory/05-contact.md,
       * sec. 6.1) at the converged @p u: every vertex an obstacle pushes
       * gets @f$\lambda_a \leftarrow \max(0, \lambda_a +
       * \varepsilon_p d_a)@f$, if that moves some @f$\lambda_a /
       * \varepsilon_p@f$ by more than @p tolerance (a penetration where
       * the vertex carries pressure, a gap where its multiplier still
       * pushes). Returns that largest move, the constraint's violation;
       * the multipliers changed iff it exceeds @p tolerance.
       */
      double
      update_multipliers(const Vector<double> &u,
                         const double          tolerance,
                         const bool            first);
      /** The constraint's violation at @p u that update_multipliers()
       * would measure, without an update. */
      double
      violation(const Vector<double> &u) const;
      /** The multipliers of all obstacles, one after the other (vertex
       * order), to be saved and restored (a cut-back, a checkpoint). */
      const std::vector<double> &
      multiplier_values() const;
      void
      set_multiplier_values(const std::vector<double> &values);

    private:
      const ContactSurface        &surface;
      std::vector<ObstacleContact> obstacles;
      /** The multiplier @f$\lambda_a@f$ (pressure units) of every
       * obstacle o and mesh vertex v at o * n_vertices + v, zero unless the
       * augmented Lagrangian is on. */
      std::vector<double> multipliers;
      /** Per obstacle: the vertices of the triangles it pushes, each once. */
      std::vector<std::vector<unsigned int>> pushed_vertices;
      /** The multiplier of obstacle @p o at vertex @p v. */
      double
      multiplier(const unsigned int o, const unsigned int v) const;
      /** G(lambda) of the Uzawa step at @p u into @p G; returns the
       * violation max |G - lambda| / eps_p. */
      double
      uzawa_map(const Vector<double> &u, std::vector<double> &G) const;
      /** The last Uzawa iterates of this increment, newest first: G(lambda)
       * and G(lambda) - lambda (the Anderson acceleration's memory). */
      struct Iterate
      {
        std::vector<double> G, f;
      };
      std::deque<Iterate>           history;
      static constexpr unsigned int max_history = 5;

      /** The energy of triangle @p t against obstacles[@p o] at the
       * vertex positions @p tri: the penalty, plus the multiplier term
       * where a vertex of the triangle has a multiplier. */
      template <typename Number>
      Number
      triangle_energy(const unsigned int                     o,
                      const unsigned int                     t,
                      const std::array<Point<3, Number>, 3> &tri) const;
      /** The area of triangle @p t (at @p tri) where obstacles[@p o]
       * presses: its penetrating part, or with multipliers the part where
       * the pressure lambda + eps_p d is positive. */
      double
      contact_area(const unsigned int             o,
                   const unsigned int             t,
                   const std::array<Point<3>, 3> &tri) const;
      /** Whether triangle @p t has a nonzero multiplier for obstacle
       * @p o. */
      bool
      has_multiplier(const unsigned int o, const unsigned int t) const;

      /** Whether obstacle @p o pushes triangle @p t. */
      bool
      pushes(const ObstacleContact &o, const unsigned int t) const;

      /** Call @p f(t, o, derivatives) for every triangle t and obstacle
       * obstacles[o] in contact. */
      template <typename F>
      void
      for_each_contact(const Vector<double> &u,
                       const bool            with_hessian,
                       const F              &f) const;
    };
  } // namespace Contact
} // namespace TissueContact
