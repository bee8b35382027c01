#pragma once

#include <tissue_contact/contact/ad_reference.h>
#include <tissue_contact/contact/contact_interaction.h>
#include <tissue_contact/contact/contact_parameters.h>
#include <tissue_contact/contact/contact_surface.h>

#include <deal.II/base/tensor.h>

#include <array>
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

    private:
      const ContactSurface        &surface;
      std::vector<ObstacleContact> obstacles;

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
