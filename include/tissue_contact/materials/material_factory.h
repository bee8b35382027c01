#pragma once

#include <tissue_contact/materials/material.h>

#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <string>

namespace TissueContact
{
  namespace Materials
  {
    using namespace dealii;

    /**
     * The material entries of a body's prm subsection ("Bodies/Body N"):
     * the model and its constants (doc/theory/03-materials.md), and the
     * optional fiber reinforcement (subsection "Fiber"). Stresses are in the
     * units of the constants (consistent units).
     */
    struct MaterialParameters
    {
      std::string model = "neo-Hookean";
      double      mu = 1., lambda = 1.;
      double      C1 = 1., C2 = 0., a = 1.;
      double      alpha = 1., beta = 1.;
      std::string formulation     = "coupled";
      double      bulk_modulus    = 1000.;
      std::string volumetric_term = "pointwise";
      std::string rotation        = "pointwise";
      bool        fiber           = false;
      double      fiber_alpha = 0., fiber_beta = 1.;
      std::string fiber_direction = "1; 0; 0";

      /** Bind the entries of the current subsection (and of its
       * subsection "Fiber") to this object. */
      void
      declare_parameters(ParameterHandler &prm);

      /** Whether the volume term is integrated at the vertices
       * (Volumetric term = nodal average,
       * doc/theory/08-nodal-pressure.md). */
      bool
      nodal_volume() const
      {
        return volumetric_term == "nodal average";
      }

      /** Whether the volume term is each element's mean dilatation's
       * (Volumetric term = element average,
       * doc/theory/09-mean-dilatation.md). */
      bool
      element_volume() const
      {
        return volumetric_term == "element average";
      }

      /** Whether the body's elements are single-rotation elements
       * (Rotation = element, doc/theory/10-single-rotation.md). */
      bool
      single_rotation() const
      {
        return rotation == "element";
      }
    };

    /**
     * The material @p parameters describe: neo-Hookean, Mooney-Rivlin,
     * Veronda, Saint Venant-Kirchhoff or linear, wrapped in a
     * FiberReinforcement when fibers are enabled; null for Model = rigid (a
     * rigid body has no material). Throws naming what is wrong (fibers on
     * the linear model, a fiber direction that does not parse).
     */
    std::unique_ptr<Material>
    create_material(const MaterialParameters &parameters);
  } // namespace Materials
} // namespace TissueContact
