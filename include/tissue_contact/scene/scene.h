#pragma once

#include <tissue_contact/base/discretization.h>
#include <tissue_contact/elasticity/elastic_assembler.h>
#include <tissue_contact/materials/material.h>
#include <tissue_contact/rigid/free_rigid_bodies.h>
#include <tissue_contact/scene/parameters.h>

#include <deal.II/grid/tria.h>

#include <memory>
#include <vector>

namespace TissueContact
{
  namespace Scene
  {
    /** A DoF whose value is prescribed: its component, the reference
     * position of its support point and the motion it follows. */
    struct PrescribedDof
    {
      types::global_dof_index dof;
      unsigned int            component;
      Point<3>                X;
      const PrescribedMotion *motion;
    };

    /**
     * The scene a parameter file describes: the mesh (checked: only
     * tetrahedra, none inverted or degenerate, every material id mapped to
     * a body, every boundary id of a condition present), one material per
     * body, the dead loads and the prescribed motions of boundaries and
     * rigid bodies. Every problem found is reported as one error naming it.
     */
    class Scene
    {
    public:
      explicit Scene(const SceneParameters &parameters);

      const SceneParameters parameters;
      Triangulation<3>      triangulation;

      /** Per material id: the material (null for rigid bodies) and density. */
      std::map<types::material_id, Elasticity::BodyData>
      body_data() const;

      /** Gravity and tractions at load factor 1. */
      Elasticity::DeadLoads
      dead_loads() const;

      /** Every prescribed DoF of @p disc: boundary conditions first, then
       * rigid bodies (a later entry for the same DoF wins). */
      std::vector<PrescribedDof>
      prescribed_dofs(const Discretization &disc) const;

      /** The free rigid bodies (Rigid motion/Free) with every DoF of their
       * cells; empty if there are none. */
      std::vector<Rigid::FreeRigidBodies::Body>
      free_rigid_bodies(const Discretization &disc) const;

    private:
      std::vector<std::unique_ptr<Materials::Material>> materials;

      void
      create_mesh();
      void
      check_mesh() const;
    };
  } // namespace Scene
} // namespace TissueContact
