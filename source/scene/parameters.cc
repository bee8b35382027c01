#include <deal.II/base/utilities.h>
#include <fstream>
#include <sstream>
#include <tissue_contact/scene/parameters.h>

namespace TissueContact
{
  namespace Scene
  {
    namespace
    {
      const std::string vector_pattern_doc = " (three numbers: x, y, z)";

      std::string
      resolve(const std::string &path, const std::string &directory)
      {
        if (path.empty() || path[0] == '/' || directory.empty())
          return path;
        return directory + "/" + path;
      }

      void
      declare_motion(ParameterHandler &prm, const std::string &what)
      {
        prm.declare_entry("Translation",
                          "0, 0, 0",
                          Patterns::List(Patterns::Double(), 3, 3),
                          "Translation d of the " + what + " at load factor 1" +
                            vector_pattern_doc);
        prm.declare_entry("Rotation axis",
                          "0, 0, 1",
                          Patterns::List(Patterns::Double(), 3, 3),
                          "Axis a of the rotation" + vector_pattern_doc);
        prm.declare_entry("Rotation center",
                          "0, 0, 0",
                          Patterns::List(Patterns::Double(), 3, 3),
                          "A point c on the rotation axis" +
                            vector_pattern_doc);
        prm.declare_entry("Rotation angle",
                          "0",
                          Patterns::Double(),
                          "Rotation angle theta in degrees at load factor 1; "
                          "u = R(lambda theta)(X - c) + c - X + lambda d.");
      }

      PrescribedMotion
      parse_motion(ParameterHandler &prm)
      {
        PrescribedMotion m;
        m.translation = parse_vector(prm.get("Translation"), "Translation");
        m.axis        = parse_vector(prm.get("Rotation axis"), "Rotation axis");
        m.center =
          Point<3>(parse_vector(prm.get("Rotation center"), "Rotation center"));
        m.angle = prm.get_double("Rotation angle") * M_PI / 180.;
        AssertThrow(m.angle == 0. || m.axis.norm() > 0.,
                    ExcMessage("Rotation axis must not be zero"));
        return m;
      }

      struct Counts
      {
        unsigned int bodies = 1, dirichlet = 1, tractions = 0, obstacles = 0,
                     pairs = 0;
      };

      void
      declare_counts(ParameterHandler &prm)
      {
        prm.enter_subsection("Bodies");
        prm.declare_entry("Number of bodies",
                          "1",
                          Patterns::Integer(1, 64),
                          "How many subsections 'Body 0', 'Body 1', ... "
                          "follow, one per material id of the mesh.");
        prm.leave_subsection();
        prm.enter_subsection("Boundary conditions");
        prm.declare_entry("Number of Dirichlet conditions",
                          "1",
                          Patterns::Integer(0, 64),
                          "How many subsections 'Dirichlet 0', ... follow.");
        prm.declare_entry("Number of tractions",
                          "0",
                          Patterns::Integer(0, 64),
                          "How many subsections 'Traction 0', ... follow.");
        prm.leave_subsection();
        prm.enter_subsection("Contact");
        prm.declare_entry("Number of obstacles",
                          "0",
                          Patterns::Integer(0, 64),
                          "How many subsections 'Obstacle 0', ... follow.");
        prm.declare_entry("Number of pairs",
                          "0",
                          Patterns::Integer(0, 64),
                          "How many subsections 'Pair 0', ... follow.");
        prm.leave_subsection();
      }

      Counts
      read_counts(const std::string &text, const std::string &name)
      {
        ParameterHandler prm;
        declare_counts(prm);
        std::istringstream in(text);
        prm.parse_input(in, name, "", /*skip_undefined=*/true);
        Counts c;
        prm.enter_subsection("Bodies");
        c.bodies = prm.get_integer("Number of bodies");
        prm.leave_subsection();
        prm.enter_subsection("Boundary conditions");
        c.dirichlet = prm.get_integer("Number of Dirichlet conditions");
        c.tractions = prm.get_integer("Number of tractions");
        prm.leave_subsection();
        prm.enter_subsection("Contact");
        c.obstacles = prm.get_integer("Number of obstacles");
        c.pairs     = prm.get_integer("Number of pairs");
        prm.leave_subsection();
        return c;
      }
    } // namespace


    Tensor<1, 3>
    parse_vector(const std::string &text, const std::string &entry)
    {
      const auto parts = Utilities::split_string_list(text, ',');
      AssertThrow(parts.size() == 3,
                  ExcMessage("entry '" + entry +
                             "' must be three numbers x, y, z, not '" + text +
                             "'"));
      Tensor<1, 3> v;
      for (unsigned int d = 0; d < 3; ++d)
        v[d] = Utilities::string_to_double(parts[d]);
      return v;
    }


    void
    MeshParameters::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Mesh");
      prm.declare_entry("Source",
                        "box",
                        Patterns::Selection("box|file"),
                        "box: a generated box of tetrahedra (material id 0, "
                        "boundary ids 0..5 on the faces x-, x+, y-, y+, z-, "
                        "z+); file: a gmsh .msh file (format 2.2 or 4) whose "
                        "physical volumes are material ids and physical "
                        "surfaces boundary ids.");
      prm.declare_entry("File",
                        "",
                        Patterns::Anything(),
                        "The gmsh mesh file (Source = file); relative to the "
                        "folder of this parameter file.");
      prm.declare_entry("Box lower corner",
                        "0, 0, 0",
                        Patterns::List(Patterns::Double(), 3, 3),
                        "Lower corner of the box" + vector_pattern_doc);
      prm.declare_entry("Box upper corner",
                        "1, 1, 1",
                        Patterns::List(Patterns::Double(), 3, 3),
                        "Upper corner of the box" + vector_pattern_doc);
      prm.declare_entry("Box subdivisions",
                        "1, 1, 1",
                        Patterns::List(Patterns::Integer(1), 3, 3),
                        "Hexahedral cells per direction; each is split into "
                        "tetrahedra.");
      prm.declare_entry("Distortion",
                        "0",
                        Patterns::Double(0., 0.4),
                        "Move interior vertices randomly by this fraction of "
                        "the local edge length (an unstructured mesh for "
                        "tests).");
      prm.declare_entry("Scale",
                        "1",
                        Patterns::Double(0.),
                        "Multiply all mesh coordinates by this factor (e.g. "
                        "0.001 for a mesh in mm and SI units).");
      prm.leave_subsection();
    }


    void
    MeshParameters::parse(ParameterHandler &prm, const std::string &dir)
    {
      prm.enter_subsection("Mesh");
      source = prm.get("Source");
      file   = prm.get("File");
      if (source == "file")
        {
          AssertThrow(!file.empty(),
                      ExcMessage("Mesh: Source = file needs a File"));
          file = resolve(file, dir);
        }
      lower =
        Point<3>(parse_vector(prm.get("Box lower corner"), "Box lower corner"));
      upper =
        Point<3>(parse_vector(prm.get("Box upper corner"), "Box upper corner"));
      const auto s = Utilities::string_to_int(
        Utilities::split_string_list(prm.get("Box subdivisions"), ','));
      subdivisions.assign(s.begin(), s.end());
      distortion = prm.get_double("Distortion");
      scale      = prm.get_double("Scale");
      AssertThrow(scale > 0., ExcMessage("Mesh: Scale must be positive"));
      for (unsigned int d = 0; d < 3; ++d)
        AssertThrow(upper[d] > lower[d],
                    ExcMessage("Mesh: Box upper corner must exceed Box lower "
                               "corner in every coordinate"));
      prm.leave_subsection();
    }


    void
    BodyParameters::declare(ParameterHandler &prm)
    {
      prm.declare_entry("Name", "body", Patterns::Anything(), "A label.");
      prm.declare_entry("Material id",
                        "0",
                        Patterns::Integer(0, 255),
                        "The material id (gmsh physical volume tag) of the "
                        "cells of this body.");
      prm.declare_entry(
        "Model",
        "neo-Hookean",
        Patterns::Selection("neo-Hookean|Mooney-Rivlin|Veronda|"
                            "Saint Venant-Kirchhoff|linear|rigid"),
        "Material model (doc/theory/03-materials.md). neo-Hookean, Saint "
        "Venant-Kirchhoff, linear: Mu, Lambda. Mooney-Rivlin: C1, C2, a. "
        "Veronda: Alpha, Beta, a. rigid: the body follows 'Rigid motion'.");
      prm.declare_entry("Density",
                        "1",
                        Patterns::Double(0.),
                        "Reference density rho0 (mass per reference volume).");
      prm.declare_entry("Mu", "1", Patterns::Double(), "Lame shear modulus.");
      prm.declare_entry("Lambda", "1", Patterns::Double(), "Lame lambda.");
      prm.declare_entry("C1", "1", Patterns::Double(), "Mooney-Rivlin C1.");
      prm.declare_entry("C2", "0", Patterns::Double(), "Mooney-Rivlin C2.");
      prm.declare_entry("a",
                        "1",
                        Patterns::Double(),
                        "Compressibility a of Mooney-Rivlin and Veronda.");
      prm.declare_entry("Alpha", "1", Patterns::Double(), "Veronda alpha.");
      prm.declare_entry("Beta", "1", Patterns::Double(), "Veronda beta.");
      prm.enter_subsection("Fiber");
      prm.declare_entry("Enabled",
                        "false",
                        Patterns::Bool(),
                        "Add fiber reinforcement to the ground material "
                        "(not for linear and rigid).");
      prm.declare_entry("Alpha", "0", Patterns::Double(), "Fiber alpha.");
      prm.declare_entry("Beta", "1", Patterns::Double(), "Fiber beta.");
      prm.declare_entry("Direction",
                        "1; 0; 0",
                        Patterns::Anything(),
                        "Fiber direction in the reference configuration: "
                        "three expressions in x, y, z separated by ';' "
                        "(normalized where evaluated).");
      prm.leave_subsection();
      prm.enter_subsection("Rigid motion");
      declare_motion(prm, "rigid body");
      prm.leave_subsection();
    }


    void
    BodyParameters::parse(ParameterHandler &prm)
    {
      name    = prm.get("Name");
      id      = prm.get_integer("Material id");
      model   = prm.get("Model");
      density = prm.get_double("Density");
      mu      = prm.get_double("Mu");
      lambda  = prm.get_double("Lambda");
      C1      = prm.get_double("C1");
      C2      = prm.get_double("C2");
      a       = prm.get_double("a");
      alpha   = prm.get_double("Alpha");
      beta    = prm.get_double("Beta");
      prm.enter_subsection("Fiber");
      fiber           = prm.get_bool("Enabled");
      fiber_alpha     = prm.get_double("Alpha");
      fiber_beta      = prm.get_double("Beta");
      fiber_direction = prm.get("Direction");
      prm.leave_subsection();
      prm.enter_subsection("Rigid motion");
      rigid_motion = parse_motion(prm);
      prm.leave_subsection();
    }


    void
    DirichletParameters::declare(ParameterHandler &prm)
    {
      prm.declare_entry("Boundary id",
                        "0",
                        Patterns::Integer(0, 255),
                        "The boundary id (gmsh physical surface tag).");
      prm.declare_entry("Components",
                        "xyz",
                        Patterns::Selection("xyz|x|y|z|xy|xz|yz"),
                        "Which displacement components are prescribed.");
      declare_motion(prm, "boundary");
    }


    void
    DirichletParameters::parse(ParameterHandler &prm)
    {
      boundary_id = prm.get_integer("Boundary id");
      components  = prm.get("Components");
      motion      = parse_motion(prm);
    }


    void
    TractionParameters::declare(ParameterHandler &prm)
    {
      prm.declare_entry("Boundary id",
                        "0",
                        Patterns::Integer(0, 255),
                        "The boundary id (gmsh physical surface tag).");
      prm.declare_entry("Traction",
                        "0, 0, 0",
                        Patterns::List(Patterns::Double(), 3, 3),
                        "Dead traction t0 per unit reference area at load "
                        "factor 1" +
                          vector_pattern_doc);
    }


    void
    TractionParameters::parse(ParameterHandler &prm)
    {
      boundary_id = prm.get_integer("Boundary id");
      traction    = parse_vector(prm.get("Traction"), "Traction");
    }


    void
    ObstacleParameters::declare(ParameterHandler &prm)
    {
      prm.declare_entry("Type",
                        "plane",
                        Patterns::Selection("plane|sphere"),
                        "A rigid plane (the bodies stay on the side its "
                        "Normal points to) or sphere (the bodies stay "
                        "outside).");
      prm.declare_entry("Point",
                        "0, 0, 0",
                        Patterns::List(Patterns::Double(), 3, 3),
                        "A point of the plane" + vector_pattern_doc);
      prm.declare_entry("Normal",
                        "0, 0, 1",
                        Patterns::List(Patterns::Double(), 3, 3),
                        "Normal of the plane, pointing out of the obstacle" +
                          vector_pattern_doc);
      prm.declare_entry("Center",
                        "0, 0, 0",
                        Patterns::List(Patterns::Double(), 3, 3),
                        "Center of the sphere" + vector_pattern_doc);
      prm.declare_entry("Radius",
                        "1",
                        Patterns::Double(0.),
                        "Radius of the sphere.");
      prm.declare_entry("Penalty factor",
                        "1000",
                        Patterns::Double(0.),
                        "eps_p in W = eps_p/2 int d^2 da over the penetrating "
                        "part of each contact triangle (d: penetration "
                        "depth); the penetration falls as 1/eps_p.");
      prm.declare_entry("Bodies",
                        "",
                        Patterns::List(Patterns::Integer(0, 255)),
                        "Material ids of the bodies the obstacle pushes "
                        "(empty: all bodies with contact surfaces).");
    }


    void
    ObstacleParameters::parse(ParameterHandler &prm)
    {
      type   = prm.get("Type");
      point  = Point<3>(parse_vector(prm.get("Point"), "Point"));
      normal = parse_vector(prm.get("Normal"), "Normal");
      AssertThrow(normal.norm() > 0.,
                  ExcMessage("Obstacle: the Normal must not be zero"));
      normal /= normal.norm();
      center  = Point<3>(parse_vector(prm.get("Center"), "Center"));
      radius  = prm.get_double("Radius");
      penalty = prm.get_double("Penalty factor");
      bodies.clear();
      for (const auto &id :
           Utilities::split_string_list(prm.get("Bodies"), ','))
        bodies.insert(Utilities::string_to_int(id));
    }


    void
    ContactPairParameters::declare(ParameterHandler &prm)
    {
      prm.declare_entry("Surface body",
                        "0",
                        Patterns::Integer(0, 255),
                        "Material id of the body whose contact triangles "
                        "are pushed out of the other body.");
      prm.declare_entry("Volume body",
                        "0",
                        Patterns::Integer(0, 255),
                        "Material id of the body whose tetrahedra and "
                        "material depth push; equal to Surface body for "
                        "self-contact. Declare both directions for two "
                        "bodies.");
      prm.declare_entry("Penalty factor",
                        "1000",
                        Patterns::Double(0.),
                        "eps_p in W = eps_p/2 int g^2 da over every "
                        "triangle-tetrahedron intersection (g: the material "
                        "depth of the volume body).");
      prm.declare_entry("Method",
                        "area integration",
                        Patterns::Selection(
                          "area integration|point collocation"),
                        "area integration: the penalty integrated exactly over "
                        "every triangle-tetrahedron intersection (continuous "
                        "forces); point collocation: sampled at the triangle "
                        "vertices only (dissertation 5.3.5, the baseline "
                        "that chatters).");
    }


    void
    ContactPairParameters::parse(ParameterHandler &prm)
    {
      surface_body      = prm.get_integer("Surface body");
      volume_body       = prm.get_integer("Volume body");
      penalty           = prm.get_double("Penalty factor");
      point_collocation = prm.get("Method") == "point collocation";
    }


    void
    TimeIntegrationParameters::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Time integration");
      prm.declare_entry("Analysis",
                        "static",
                        Patterns::Selection("static|dynamic"),
                        "static: incremental loading to equilibrium (no "
                        "mass); dynamic: integrate the equations of motion "
                        "in time (doc/theory/06-dynamics.md).");
      prm.declare_entry("Scheme",
                        "Newmark",
                        Patterns::Selection(
                          "Newmark|implicit Euler|central difference|IDA|"
                          "quasistatic"),
                        "Newmark (beta, gamma below; average acceleration by "
                        "default: no numerical damping), implicit Euler "
                        "(dissipative), central difference (explicit, lumped "
                        "mass, stable below 2/omega_max), IDA (SUNDIALS' "
                        "variable-order BDF with error control; settings in "
                        "the subsection IDA, whose times are replaced by End "
                        "time and Output interval), quasistatic (no inertia: "
                        "the damping C = alpha M + beta K_0 as a viscosity, "
                        "C v + f_int(u) = f_ext(t) by backward Euler; "
                        "without damping a sequence of static solves).");
      {
        // deal.II's IDA entries, bound to a dummy object; parse() reads
        // them back by name
        static SUNDIALS::IDA<Vector<double>>::AdditionalData declared;
        prm.enter_subsection("IDA");
        declared.add_parameters(prm);
        prm.leave_subsection();
      }
      prm.declare_entry("Time step", "0.01", Patterns::Double(0.), "");
      prm.declare_entry("End time", "1", Patterns::Double(0.), "");
      prm.declare_entry("Minimum time step",
                        "1e-8",
                        Patterns::Double(0.),
                        "An implicit step whose Newton solve fails is halved "
                        "and retried; below this size the run stops.");
      prm.declare_entry("Growth factor",
                        "1",
                        Patterns::Double(1.),
                        "After a step with at most 3 Newton iterations the "
                        "next may grow by this factor (up to Time step).");
      prm.declare_entry("Newmark beta", "0.25", Patterns::Double(0., 0.5), "");
      prm.declare_entry("Newmark gamma", "0.5", Patterns::Double(0., 1.), "");
      prm.declare_entry("Rayleigh alpha",
                        "0",
                        Patterns::Double(0.),
                        "Damping C = alpha M + beta K_0 (K_0: the tangent at "
                        "the start).");
      prm.declare_entry("Rayleigh beta",
                        "0",
                        Patterns::Double(0.),
                        "beta of C = alpha M + beta K (K: see Rayleigh "
                        "tangent).");
      prm.declare_entry(
        "Rayleigh tangent",
        "initial",
        Patterns::Selection("initial|step start"),
        "The K of beta K. initial: K_0, the tangent at the initial state "
        "(constant, but not objective: it over-damps slender bodies that "
        "have rotated, doc/theory/06-dynamics.md sec. 1); step start: the "
        "tangent at the start of every implicit step, which follows the "
        "rotation (one more assembly per step; the explicit scheme and IDA "
        "keep K_0).");
      prm.declare_entry(
        "Nodal viscosity",
        "0",
        Patterns::Double(0.),
        "A time tau: the dissertation's nodal viscosity D_a = tau sum_e "
        "mu_e h_e / n_e (the diagonal of the static solver's "
        "quasi-viscosity, doc/theory/04 sec. 4.4) added to the damping C as "
        "a physical damping; a node's viscous force D_a v equals the "
        "elastic force of its elements at the displacement tau v.");
      prm.declare_entry("Mass",
                        "consistent",
                        Patterns::Selection("consistent|lumped"),
                        "The implicit schemes may use either; central "
                        "difference always uses the lumped (HRZ) mass.");
      prm.declare_entry("Ramp time",
                        "0",
                        Patterns::Double(0.),
                        "Loads and prescribed motions grow linearly from "
                        "zero over this time (0: applied at t = 0).");
      prm.declare_entry("Output interval",
                        "0",
                        Patterns::Double(0.),
                        "Time between VTU outputs (0: every step).");
      prm.leave_subsection();
    }


    void
    TimeIntegrationParameters::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Time integration");
      dynamic           = prm.get("Analysis") == "dynamic";
      use_ida           = prm.get("Scheme") == "IDA";
      integrator.scheme = use_ida ?
                            Dynamics::Scheme::implicit_euler :
                            Dynamics::scheme_from_string(prm.get("Scheme"));
      prm.enter_subsection("IDA");
      prm.enter_subsection("Error control");
      ida.absolute_tolerance = prm.get_double("Absolute error tolerance");
      ida.relative_tolerance = prm.get_double("Relative error tolerance");
      ida.ignore_algebraic_terms_for_errors =
        prm.get_bool("Ignore algebraic terms for error computations");
      prm.leave_subsection();
      prm.enter_subsection("Running parameters");
      ida.initial_step_size = prm.get_double("Initial step size");
      ida.minimum_step_size = prm.get_double("Minimum step size");
      ida.maximum_order     = prm.get_integer("Maximum order of BDF");
      ida.maximum_non_linear_iterations =
        prm.get_integer("Maximum number of nonlinear iterations");
      prm.leave_subsection();
      prm.leave_subsection();
      ida.ic_type    = SUNDIALS::IDA<Vector<double>>::AdditionalData::none;
      ida.reset_type = SUNDIALS::IDA<Vector<double>>::AdditionalData::none;
      time_step      = prm.get_double("Time step");
      end_time       = prm.get_double("End time");
      integrator.minimum_step   = prm.get_double("Minimum time step");
      integrator.growth_factor  = prm.get_double("Growth factor");
      integrator.maximum_step   = time_step;
      integrator.beta           = prm.get_double("Newmark beta");
      integrator.gamma          = prm.get_double("Newmark gamma");
      integrator.rayleigh_alpha = prm.get_double("Rayleigh alpha");
      integrator.rayleigh_beta  = prm.get_double("Rayleigh beta");
      integrator.rayleigh_beta_current =
        prm.get("Rayleigh tangent") == "step start";
      integrator.nodal_viscosity = prm.get_double("Nodal viscosity");
      integrator.ramp_time       = prm.get_double("Ramp time");
      lumped_mass                = prm.get("Mass") == "lumped";
      output_interval            = prm.get_double("Output interval");
      prm.leave_subsection();
      ida.initial_time  = 0.;
      ida.final_time    = end_time;
      ida.output_period = output_interval > 0. ? output_interval : time_step;
      AssertThrow(!dynamic || (time_step > 0. && end_time > 0.),
                  ExcMessage("Time integration: a dynamic analysis needs "
                             "Time step > 0 and End time > 0"));
      AssertThrow(integrator.scheme != Dynamics::Scheme::newmark ||
                    integrator.beta > 0.,
                  ExcMessage("Time integration: Newmark beta must be > 0 "
                             "for the implicit Newmark scheme"));
    }


    void
    OutputParameters::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      prm.declare_entry("Directory",
                        "output",
                        Patterns::Anything(),
                        "Folder for VTU/PVD files and the convergence log "
                        "(relative to the current folder); created if "
                        "missing.");
      prm.declare_entry("Base name",
                        "solution",
                        Patterns::Anything(),
                        "Files are <base>-NNNN.vtu, <base>.pvd and "
                        "<base>-convergence.csv.");
      prm.declare_entry("Write VTU",
                        "true",
                        Patterns::Bool(),
                        "Write a VTU file per converged increment and the "
                        "PVD series.");
      prm.declare_entry("Print timing",
                        "true",
                        Patterns::Bool(),
                        "Print the wall-clock time summary at the end.");
      prm.leave_subsection();
    }


    void
    OutputParameters::parse(ParameterHandler &prm, const std::string &)
    {
      prm.enter_subsection("Output");
      directory    = prm.get("Directory");
      base_name    = prm.get("Base name");
      write_vtu    = prm.get_bool("Write VTU");
      print_timing = prm.get_bool("Print timing");
      prm.leave_subsection();
    }


    void
    SceneParameters::declare(ParameterHandler  &prm,
                             const unsigned int n_bodies,
                             const unsigned int n_dirichlet,
                             const unsigned int n_tractions,
                             const unsigned int n_obstacles,
                             const unsigned int n_pairs)
    {
      declare_counts(prm);
      MeshParameters::declare(prm);
      prm.enter_subsection("Discretization");
      prm.declare_entry("Polynomial degree",
                        "1",
                        Patterns::Integer(1, 2),
                        "1: linear tetrahedra (fast); 2: quadratic "
                        "tetrahedra (accurate, no locking in bending).");
      prm.leave_subsection();

      prm.enter_subsection("Bodies");
      for (unsigned int i = 0; i < n_bodies; ++i)
        {
          prm.enter_subsection("Body " + std::to_string(i));
          BodyParameters::declare(prm);
          prm.leave_subsection();
        }
      prm.leave_subsection();

      prm.enter_subsection("Boundary conditions");
      for (unsigned int i = 0; i < n_dirichlet; ++i)
        {
          prm.enter_subsection("Dirichlet " + std::to_string(i));
          DirichletParameters::declare(prm);
          prm.leave_subsection();
        }
      for (unsigned int i = 0; i < n_tractions; ++i)
        {
          prm.enter_subsection("Traction " + std::to_string(i));
          TractionParameters::declare(prm);
          prm.leave_subsection();
        }
      prm.leave_subsection();

      prm.enter_subsection("Loads");
      prm.declare_entry("Gravity",
                        "0, 0, 0",
                        Patterns::List(Patterns::Double(), 3, 3),
                        "Body force per unit mass g at load factor 1 "
                        "(multiplied by each body's density)" +
                          vector_pattern_doc);
      prm.leave_subsection();

      prm.enter_subsection("Contact");
      prm.declare_entry("Contact surfaces",
                        "",
                        Patterns::List(Patterns::Integer(0, 255)),
                        "Boundary ids whose faces are contact surfaces (a "
                        "cut plane with a Dirichlet condition is not). "
                        "Empty: no contact, and no contact search at all.");
      for (unsigned int i = 0; i < n_obstacles; ++i)
        {
          prm.enter_subsection("Obstacle " + std::to_string(i));
          ObstacleParameters::declare(prm);
          prm.leave_subsection();
        }
      for (unsigned int i = 0; i < n_pairs; ++i)
        {
          prm.enter_subsection("Pair " + std::to_string(i));
          ContactPairParameters::declare(prm);
          prm.leave_subsection();
        }
      prm.leave_subsection();

      Solvers::IncrementalNewtonSolver::Parameters::declare(prm);
      TimeIntegrationParameters::declare(prm);
      OutputParameters::declare(prm);
    }


    void
    SceneParameters::parse(ParameterHandler &prm, const std::string &dir)
    {
      mesh.parse(prm, dir);
      prm.enter_subsection("Discretization");
      degree = prm.get_integer("Polynomial degree");
      prm.leave_subsection();

      prm.enter_subsection("Bodies");
      for (unsigned int i = 0; i < bodies.size(); ++i)
        {
          prm.enter_subsection("Body " + std::to_string(i));
          bodies[i].parse(prm);
          prm.leave_subsection();
        }
      prm.leave_subsection();

      prm.enter_subsection("Boundary conditions");
      for (unsigned int i = 0; i < dirichlet.size(); ++i)
        {
          prm.enter_subsection("Dirichlet " + std::to_string(i));
          dirichlet[i].parse(prm);
          prm.leave_subsection();
        }
      for (unsigned int i = 0; i < tractions.size(); ++i)
        {
          prm.enter_subsection("Traction " + std::to_string(i));
          tractions[i].parse(prm);
          prm.leave_subsection();
        }
      prm.leave_subsection();

      prm.enter_subsection("Loads");
      gravity = parse_vector(prm.get("Gravity"), "Gravity");
      prm.leave_subsection();

      prm.enter_subsection("Contact");
      contact.surfaces.clear();
      for (const auto &id :
           Utilities::split_string_list(prm.get("Contact surfaces"), ','))
        contact.surfaces.insert(Utilities::string_to_int(id));
      for (unsigned int i = 0; i < contact.obstacles.size(); ++i)
        {
          prm.enter_subsection("Obstacle " + std::to_string(i));
          contact.obstacles[i].parse(prm);
          prm.leave_subsection();
        }
      for (unsigned int i = 0; i < contact.pairs.size(); ++i)
        {
          prm.enter_subsection("Pair " + std::to_string(i));
          contact.pairs[i].parse(prm);
          prm.leave_subsection();
        }
      prm.leave_subsection();
      AssertThrow((contact.obstacles.empty() && contact.pairs.empty()) ||
                    !contact.surfaces.empty(),
                  ExcMessage("Contact: obstacles or pairs are declared but no "
                             "Contact surfaces; list the boundary ids that "
                             "can touch"));

      solver.parse(prm);
      time_integration.parse(prm);
      time_integration.integrator.newton = solver;
      output.parse(prm, dir);
    }


    SceneParameters
    SceneParameters::parse_text(const std::string &text,
                                const std::string &name,
                                const std::string &directory)
    {
      const Counts     counts = read_counts(text, name);
      ParameterHandler prm;
      declare(prm,
              counts.bodies,
              counts.dirichlet,
              counts.tractions,
              counts.obstacles,
              counts.pairs);
      std::istringstream in(text);
      prm.parse_input(in, name);
      SceneParameters p;
      p.bodies.resize(counts.bodies);
      p.dirichlet.resize(counts.dirichlet);
      p.tractions.resize(counts.tractions);
      p.contact.obstacles.resize(counts.obstacles);
      p.contact.pairs.resize(counts.pairs);
      p.parse(prm, directory);
      return p;
    }


    SceneParameters
    SceneParameters::from_file(const std::string &filename)
    {
      std::ifstream in(filename);
      AssertThrow(in.good(),
                  ExcMessage("cannot open the parameter file '" + filename +
                             "'"));
      std::stringstream text;
      text << in.rdbuf();
      const auto        slash = filename.rfind('/');
      const std::string directory =
        slash == std::string::npos ? "" : filename.substr(0, slash);
      return parse_text(text.str(), filename, directory);
    }


    SceneParameters
    SceneParameters::from_string(const std::string &text)
    {
      return parse_text(text, "input", "");
    }
  } // namespace Scene
} // namespace TissueContact
