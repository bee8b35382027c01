#pragma once

#include <tissue_contact/contact/analytic_obstacle.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <map>
#include <set>
#include <vector>

namespace TissueContact
{
  namespace Contact
  {
    using namespace dealii;

    /** The body material id @p m belongs to under @p body_of (itself where
     * @p body_of does not list it). */
    inline types::material_id
    body_of_material(
      const std::map<types::material_id, types::material_id> &body_of,
      const types::material_id                                m)
    {
      const auto it = body_of.find(m);
      return it == body_of.end() ? m : it->second;
    }

    /**
     * prm subsection "Contact/Obstacle N": a rigid obstacle, its penalty
     * factor @f$\varepsilon_p@f$ and the bodies (material ids; empty: all)
     * whose contact triangles it pushes (doc/theory/05-contact.md, sec. 6).
     */
    struct ObstacleContact
    {
      AnalyticObstacle             obstacle;
      double                       penalty = 1e3;
      std::set<types::material_id> bodies;

      /** Bind the entries of the current subsection to this object. */
      void
      declare_parameters(ParameterHandler &prm);
      /** Check and normalize what was read (the plane's normal). */
      void
      parse_parameters(ParameterHandler &prm);
    };

    /**
     * prm subsection "Contact/Pair N": the contact triangles of
     * @p surface_body against the tetrahedra and material depth of
     * @p volume_body (the same body for self-contact), with the penalty
     * factor @f$\varepsilon_p@f$ (doc/theory/05-contact.md, sec. 3).
     */
    struct BodyContact
    {
      types::material_id surface_body = 0, volume_body = 0;
      double             penalty = 1e3;
      /** The point-collocation baseline instead of area integration. */
      bool point_collocation = false;

      /** Bind the entries of the current subsection to this object. */
      void
      declare_parameters(ParameterHandler &prm);
    };

    /**
     * prm subsection "Contact": which boundary ids are contact surfaces,
     * the body pairs "Pair 0", ... and the rigid obstacles "Obstacle 0",
     * .... The numbers of pairs and obstacles are entries of the section
     * too: declare_parameters() declares as many subsections as the
     * vectors hold, so a file is read twice, first for the numbers
     * (Scene::SceneParameters does this).
     */
    struct Parameters
    {
      std::set<types::boundary_id> surfaces;
      std::vector<ObstacleContact> obstacles;
      std::vector<BodyContact>     pairs;
      unsigned int                 n_obstacles = 0, n_pairs = 0;
      /** The augmented-Lagrangian (Uzawa) loop on the obstacles
       * (doc/theory/05-contact.md, sec. 6.1): after each converged load
       * increment the multipliers take the contact pressure and the
       * increment is solved again, until the contact is violated by no
       * more than penetration_tolerance (no vertex penetrates by more, no
       * multiplier pushes a vertex that lifted off by more) or
       * max_multiplier_updates updates are spent. */
      bool         augmented_lagrangian   = false;
      double       penetration_tolerance  = 1e-6;
      unsigned int max_multiplier_updates = 20;
      /** The body each material id belongs to, where it is not its own
       * (set by the scene from the bodies' "Contact body" entries): the
       * bodies of pairs and obstacles are these ids. */
      std::map<types::material_id, types::material_id> body_of_material;


      /** Whether the scene asks for any contact (else no contact search
       * at all). */
      bool
      enabled() const
      {
        return !obstacles.empty() || !pairs.empty();
      }

      /** Enter "Contact" and bind its entries and those of
       * obstacles.size() obstacles and pairs.size() pairs. */
      void
      declare_parameters(ParameterHandler &prm);
      /** Check what was read (obstacles and pairs need contact surfaces). */
      void
      parse_parameters(ParameterHandler &prm);
    };
  } // namespace Contact
} // namespace TissueContact
