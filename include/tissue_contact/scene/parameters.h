#pragma once

#include <tissue_contact/contact/contact_parameters.h>
#include <tissue_contact/dynamics/time_integrator.h>
#include <tissue_contact/materials/material_factory.h>
#include <tissue_contact/scene/prescribed_motion.h>
#include <tissue_contact/solvers/newton_solver.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/sundials/ida.h>

#include <string>
#include <vector>

namespace TissueContact
{
  namespace Scene
  {
    using namespace dealii;

    /** prm subsection "Mesh": a gmsh mesh file, a gmsh geometry meshed by
     * running gmsh, or a generated box. */
    struct MeshParameters
    {
      std::string               source = "box";
      std::string               file;
      std::string               gmsh_options;
      Point<3>                  lower, upper{1., 1., 1.};
      std::vector<unsigned int> subdivisions{1, 1, 1};
      double                    distortion = 0.;
      double                    scale      = 1.;

      /** Bind the entries of this section to this object. */
      void
      declare_parameters(ParameterHandler &prm);
      /** Check what was read; relative paths are taken relative to
       * @p prm_directory. */
      void
      parse_parameters(ParameterHandler &prm, const std::string &prm_directory);
    };

    /** prm subsection "Bodies/Body N": one body (a material id) and its
     * material, density, optional fibers, or its rigid motion. */
    struct BodyParameters
    {
      std::string        name    = "body";
      types::material_id id      = 0;
      double             density = 1.;
      /** The material id of the body this material belongs to for contact
       * (-1: its own): materials with the same contact body form one body,
       * e.g. grades from muscle to tendon. */
      int                           contact_body = -1;
      Materials::MaterialParameters material;
      PrescribedMotion              rigid_motion;
      /** A rigid body whose motion is unknown (six DoFs, doc/theory/07)
       * instead of prescribed by rigid_motion. */
      bool free_rigid = false;

      /** Whether the body is rigid with a prescribed motion. */
      bool
      prescribed_rigid() const
      {
        return material.model == "rigid" && !free_rigid;
      }

      /** Bind the entries of the current subsection to this object (the
       * material's to @p material). */
      void
      declare_parameters(ParameterHandler &prm);
      /** Check what was read. */
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** prm subsection "Boundary conditions/Dirichlet N": a prescribed
     * displacement (clamp, translation, rigid rotation) of chosen
     * components on one boundary id. */
    struct DirichletParameters
    {
      types::boundary_id boundary_id = 0;
      std::string        components  = "xyz";
      PrescribedMotion   motion;

      /** Bind the entries of the current subsection to this object. */
      void
      declare_parameters(ParameterHandler &prm);
      /** Check what was read. */
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** prm subsection "Boundary conditions/Traction N": a dead reference
     * traction on one boundary id. */
    struct TractionParameters
    {
      types::boundary_id boundary_id = 0;
      Tensor<1, 3>       traction;

      /** Bind the entries of the current subsection to this object. */
      void
      declare_parameters(ParameterHandler &prm);
    };

    /** prm subsection "Output". */
    struct OutputParameters
    {
      std::string  directory        = "output";
      std::string  base_name        = "solution";
      bool         write_vtu        = true;
      bool         print_timing     = true;
      unsigned int every_n_steps    = 1;
      bool         double_precision = false;
      std::string  length_unit, force_unit;
      std::string  old_results      = "remove";
      unsigned int checkpoint_every = 1;

      /** Enter "Output" and bind its entries to this object. */
      void
      declare_parameters(ParameterHandler &prm);
    };

    /**
     * All parameters of a scene. The numbers of bodies, Dirichlet conditions
     * and tractions are read first; then every subsection is declared and
     * the file is parsed strictly: an unknown or malformed entry stops with
     * an error naming it and its line.
     */
    struct SceneParameters
    {
      /** Every entry with the value it has after parsing (read or
       * default), as a parameter file; written to the output folder at the
       * start of a run. */
      std::string effective_parameters;

      MeshParameters mesh;
      unsigned int   degree = 1;
      /** P2's stiffness quadrature: "full" (14 points) or "reduced" (6). */
      std::string stiffness_quadrature = "full";
      /** "as meshed" or "Cuthill-McKee" (Discretization). */
      std::string                      dof_numbering = "Cuthill-McKee";
      std::vector<BodyParameters>      bodies;
      std::vector<DirichletParameters> dirichlet;
      std::vector<TractionParameters>  tractions;
      Tensor<1, 3>                     gravity;
      Contact::Parameters              contact;
      Solvers::IncrementalNewtonSolver::Parameters solver;
      Dynamics::TimeIntegrator::Parameters         time_integration;
      OutputParameters                             output;

      /** Numbers of bodies, Dirichlet conditions and tractions (entries of
       * the prm; the vectors above hold as many). */
      unsigned int n_bodies = 1, n_dirichlet = 1, n_tractions = 0;

      SceneParameters();

      /** Make room for the given numbers of subsections. */
      void
      resize(const unsigned int n_bodies,
             const unsigned int n_dirichlet,
             const unsigned int n_tractions,
             const unsigned int n_obstacles,
             const unsigned int n_pairs);

      /** Declare every entry: the scene's own sections and the modules'
       * (contact, solvers, time integration), with as many subsections as
       * the vectors hold; the modules' entries are bound to this object. */
      void
      declare_parameters(ParameterHandler &prm);

      /** The parameter reference: every entry, with one subsection of each
       * kind, as `tissue-contact --print-parameters[=FORMAT]` prints it:
       * @p format "prm" (a parameter file with every entry documented),
       * "json" (ParameterHandler's JSON: value, default, documentation,
       * pattern) or "markdown" (doc/users/parameters.md: one table per
       * subsection with entry, default, allowed values and description).
       * Throws for another format. */
      static void
      print_reference(std::ostream &out, const std::string &format = "prm");

      /** The entries declared in @p prm as the Markdown reference page. */
      static void
      print_markdown(ParameterHandler &prm, std::ostream &out);

      /** Read a prm file. Relative paths in it are taken relative to the
       * file's folder. */
      static SceneParameters
      from_file(const std::string &filename);

      /** Read prm text (relative paths: the current folder). */
      static SceneParameters
      from_string(const std::string &text);

    private:
      static SceneParameters
      parse_text(const std::string &text,
                 const std::string &name,
                 const std::string &directory);
      /** Read the scene's own sections and check the modules' after
       * ParameterHandler::parse_input(). */
      void
      parse_parameters(ParameterHandler &prm, const std::string &prm_directory);
    };

  } // namespace Scene
} // namespace TissueContact
