#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/sundials/ida.h>
#include <string>
#include <tissue_contact/dynamics/time_integrator.h>
#include <tissue_contact/scene/prescribed_motion.h>
#include <tissue_contact/solvers/newton_solver.h>
#include <vector>

namespace TissueContact
{
  namespace Scene
  {
    using namespace dealii;

    /** prm subsection "Mesh": a gmsh file or a generated box. */
    struct MeshParameters
    {
      std::string               source = "box";
      std::string               file;
      Point<3>                  lower, upper{1., 1., 1.};
      std::vector<unsigned int> subdivisions{1, 1, 1};
      double                    distortion = 0.;
      double                    scale      = 1.;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm, const std::string &prm_directory);
    };

    /** prm subsection "Bodies/Body N": one body (a material id) and its
     * material, density, optional fibers, or its rigid motion. */
    struct BodyParameters
    {
      std::string        name    = "body";
      types::material_id id      = 0;
      std::string        model   = "neo-Hookean";
      double             density = 1.;
      double             mu = 1., lambda = 1.;
      double             C1 = 1., C2 = 0., a = 1.;
      double             alpha = 1., beta = 1.;
      bool               fiber       = false;
      double             fiber_alpha = 0., fiber_beta = 1.;
      std::string        fiber_direction = "1; 0; 0";
      PrescribedMotion   rigid_motion;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    /** prm subsection "Boundary conditions/Dirichlet N": a prescribed
     * displacement (clamp, translation, rigid rotation) of chosen
     * components on one boundary id. */
    struct DirichletParameters
    {
      types::boundary_id boundary_id = 0;
      std::string        components  = "xyz";
      PrescribedMotion   motion;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    /** prm subsection "Boundary conditions/Traction N": a dead reference
     * traction on one boundary id. */
    struct TractionParameters
    {
      types::boundary_id boundary_id = 0;
      Tensor<1, 3>       traction;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    /** prm subsection "Contact/Obstacle N": a rigid plane or sphere. */
    struct ObstacleParameters
    {
      std::string                  type = "plane";
      Point<3>                     point;
      Tensor<1, 3>                 normal{{0., 0., 1.}};
      Point<3>                     center;
      double                       radius  = 1.;
      double                       penalty = 1e3;
      std::set<types::material_id> bodies;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    /** prm subsection "Contact/Pair N": the contact triangles of one body
     * against the tetrahedra of another (or the same: self-contact). */
    struct ContactPairParameters
    {
      types::material_id surface_body = 0, volume_body = 0;
      double             penalty           = 1e3;
      bool               point_collocation = false;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    /** prm subsection "Contact": which boundary ids are contact surfaces,
     * the body pairs and the obstacles. */
    struct ContactParameters
    {
      std::set<types::boundary_id>       surfaces;
      std::vector<ContactPairParameters> pairs;
      std::vector<ObstacleParameters>    obstacles;
    };

    /** prm subsection "Time integration": static (default) or dynamic
     * analysis, and the time integrator's settings. */
    struct TimeIntegrationParameters
    {
      bool                                 dynamic = false;
      Dynamics::TimeIntegrator::Parameters integrator;
      double                               time_step       = 0.01;
      double                               end_time        = 1.;
      double                               output_interval = 0.;
      bool                                 lumped_mass     = false;
      /** Scheme = IDA: SUNDIALS' IDA with these settings (subsection
       * "Time integration/IDA"; its times come from End time and Output
       * interval). */
      bool                                          use_ida = false;
      SUNDIALS::IDA<Vector<double>>::AdditionalData ida;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };

    /** prm subsection "Output". */
    struct OutputParameters
    {
      std::string directory    = "output";
      std::string base_name    = "solution";
      bool        write_vtu    = true;
      bool        print_timing = true;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm, const std::string &prm_directory);
    };

    /**
     * All parameters of a scene. The numbers of bodies, Dirichlet conditions
     * and tractions are read first; then every subsection is declared and
     * the file is parsed strictly: an unknown or malformed entry stops with
     * an error naming it and its line.
     */
    struct SceneParameters
    {
      MeshParameters                               mesh;
      unsigned int                                 degree = 1;
      std::vector<BodyParameters>                  bodies;
      std::vector<DirichletParameters>             dirichlet;
      std::vector<TractionParameters>              tractions;
      Tensor<1, 3>                                 gravity;
      ContactParameters                            contact;
      Solvers::IncrementalNewtonSolver::Parameters solver;
      TimeIntegrationParameters                    time_integration;
      OutputParameters                             output;

      /** Declare everything, with the given numbers of subsections. */
      static void
      declare(ParameterHandler  &prm,
              const unsigned int n_bodies    = 1,
              const unsigned int n_dirichlet = 1,
              const unsigned int n_tractions = 1,
              const unsigned int n_obstacles = 1,
              const unsigned int n_pairs     = 1);

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
      void
      parse(ParameterHandler &prm, const std::string &prm_directory);
    };

    /** Parse "a, b, c" into a tensor; throws naming @p entry otherwise. */
    Tensor<1, 3>
    parse_vector(const std::string &text, const std::string &entry);
  } // namespace Scene
} // namespace TissueContact
