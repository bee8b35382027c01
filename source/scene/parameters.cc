#include <tissue_contact/base/parameter_tools.h>
#include <tissue_contact/scene/parameters.h>

#include <deal.II/base/utilities.h>

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace TissueContact
{
  namespace Scene
  {
    namespace
    {
      std::string
      resolve(const std::string &path, const std::string &directory)
      {
        if (path.empty() || path[0] == '/' || directory.empty())
          return path;
        return directory + "/" + path;
      }

      /** Bind the entries of a prescribed rigid motion to @p m (the
       * angle is given in degrees, kept in radians). */
      void
      declare_motion(ParameterHandler  &prm,
                     const std::string &what,
                     PrescribedMotion  &m)
      {
        prm.add_parameter("Translation",
                          m.translation,
                          "Translation d of the " + what +
                            " at load factor 1, in length units" +
                            vector_pattern_doc,
                          vector_pattern());
        prm.declare_entry(
          "Translation path",
          "",
          Patterns::List(
            Patterns::List(Patterns::Double(), 3, 3, ","), 0, 1000, ";"),
          "Instead of Translation: waypoints d0; d1; ...; dn of the "
          "translation of the " +
            what +
            ", in length units, reached at the load factors k/n and joined "
            "by straight segments (a zigzag path, say), each as three "
            "numbers x, y, z, separated by ';'. Empty: the translation is "
            "lambda d. The rotation still grows as lambda theta.");
        prm.add_action("Translation path", [&m](const std::string &list) {
          m.path.clear();
          for (const auto &point : Utilities::split_string_list(list, ';'))
            {
              const std::vector<double> x = Utilities::string_to_double(
                Utilities::split_string_list(point));
              m.path.emplace_back(Tensor<1, 3>({x[0], x[1], x[2]}));
            }
        });
        prm.add_parameter("Rotation axis",
                          m.axis,
                          "Axis a of the rotation, any nonzero length" +
                            vector_pattern_doc,
                          vector_pattern());
        prm.add_parameter("Rotation center",
                          m.center,
                          "A point c on the rotation axis, in length units" +
                            vector_pattern_doc,
                          vector_pattern());
        prm.declare_entry("Rotation angle",
                          "0",
                          Patterns::Double(),
                          "Rotation angle theta in degrees (any sign) at load "
                          "factor 1; u = R(lambda theta)(X - c) + c - X + "
                          "lambda d.");
        prm.add_action("Rotation angle", [&m](const std::string &degrees) {
          m.angle = Utilities::string_to_double(degrees) * M_PI / 180.;
        });
      }

      /** Bind the entry "Boundary id" of a condition to @p id. */
      void
      add_boundary_id(ParameterHandler &prm, types::boundary_id &id)
      {
        prm.add_parameter("Boundary id",
                          id,
                          "The boundary id (gmsh physical surface tag, "
                          "0..255).",
                          Patterns::Integer(0, 255));
      }

      void
      check_motion(const PrescribedMotion &m)
      {
        AssertThrow(m.angle == 0. || m.axis.norm() > 0.,
                    ExcMessage("Rotation axis must not be zero"));
        AssertThrow(m.path.empty() || m.translation.norm() == 0.,
                    ExcMessage("set either Translation or Translation path, "
                               "not both"));
        AssertThrow(m.path.empty() || m.path.size() >= 2,
                    ExcMessage("a Translation path needs at least two "
                               "waypoints (it has one)"));
      }
    } // namespace


    void
    MeshParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Mesh");
      prm.add_parameter("Source",
                        source,
                        "box: a generated box of tetrahedra (material id 0, "
                        "boundary ids 0..5 on the faces x-, x+, y-, y+, z-, "
                        "z+); file: a gmsh .msh file (format 2.2 or 4) whose "
                        "physical volumes are material ids and physical "
                        "surfaces boundary ids; geo: a gmsh geometry (.geo) "
                        "meshed at the start of the run by the program gmsh "
                        "(gmsh -3 with the Gmsh options), with the same "
                        "meaning of its physical groups.",
                        Patterns::Selection("box|file|geo"));
      prm.add_parameter("File",
                        file,
                        "The gmsh mesh file (Source = file) or geometry "
                        "(Source = geo); relative to the folder of this "
                        "parameter file.",
                        Patterns::Anything());
      prm.add_parameter("Gmsh options",
                        gmsh_options,
                        "For Source = geo: options passed to gmsh, e.g. "
                        "'-setnumber h 0.012' to set the geometry's "
                        "parameter h (see the comments of the .geo file).",
                        Patterns::Anything());
      prm.add_parameter("Box lower corner",
                        lower,
                        "Lower corner of the box, in length units" +
                          vector_pattern_doc,
                        vector_pattern());
      prm.add_parameter("Box upper corner",
                        upper,
                        "Upper corner of the box, in length units; above the "
                        "lower corner in every coordinate" +
                          vector_pattern_doc,
                        vector_pattern());
      prm.add_parameter("Box subdivisions",
                        subdivisions,
                        "Hexahedral cells per direction (three integers >= "
                        "1); each is split into tetrahedra.",
                        Patterns::List(Patterns::Integer(1), 3, 3));
      prm.add_parameter("Distortion",
                        distortion,
                        "Move interior vertices randomly by this fraction "
                        "(0..0.4) of the local edge length (an unstructured "
                        "mesh for tests).",
                        Patterns::Double(0., 0.4));
      prm.add_parameter("Scale",
                        scale,
                        "Multiply all mesh coordinates by this factor (> 0; "
                        "e.g. 0.001 for a mesh in mm and SI units).",
                        Patterns::Double(0.));
      prm.leave_subsection();
    }


    void
    MeshParameters::parse_parameters(ParameterHandler &, const std::string &dir)
    {
      if (source == "file" || source == "geo")
        {
          AssertThrow(!file.empty(),
                      ExcMessage("Mesh: Source = " + source + " needs a File"));
          file = resolve(file, dir);
        }
      AssertThrow(scale > 0., ExcMessage("Mesh: Scale must be positive"));
      for (unsigned int d = 0; d < 3; ++d)
        AssertThrow(upper[d] > lower[d],
                    ExcMessage("Mesh: Box upper corner must exceed Box lower "
                               "corner in every coordinate"));
    }


    void
    BodyParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.add_parameter("Name",
                        name,
                        "A label, used in messages and the run summary.",
                        Patterns::Anything());
      prm.add_parameter("Material id",
                        id,
                        "The material id (gmsh physical volume tag, 0..255) "
                        "of the cells of this body.",
                        Patterns::Integer(0, 255));
      prm.add_parameter("Density",
                        density,
                        "Reference density rho0 (mass per reference volume, "
                        "consistent units; >= 0).",
                        Patterns::Double(0.));
      prm.add_parameter(
        "Contact body",
        contact_body,
        "For contact, the material id of the body this material belongs "
        "to (-1: its own, 0..255: the Material id of another body). "
        "Materials with the same contact body are one body: its material "
        "depth is measured to the contact boundary of all of them, across "
        "their interfaces, and Contact pairs and obstacles name it by that "
        "id (a body of graded materials, e.g. muscle to tendon).",
        Patterns::Integer(-1, 255));
      material.declare_parameters(prm);
      prm.enter_subsection("Rigid motion");
      prm.add_parameter(
        "Free",
        free_rigid,
        "For Model = rigid: false, the body follows the motion below; true, "
        "its motion is unknown, six DoFs (the displacement of its center, "
        "the mean of its nodes, and a rotation vector) found by equilibrium "
        "with the bodies attached to it (shared nodes), its contacts and its "
        "loads, like FEBio's rigid bodies (doc/theory/07). A free body needs "
        "something attached or touching; static runs only; leave the motion "
        "below at zero.",
        Patterns::Bool());
      declare_motion(prm, "rigid body", rigid_motion);
      prm.leave_subsection();
    }


    void
    BodyParameters::parse_parameters(ParameterHandler &)
    {
      check_motion(rigid_motion);
      if (!free_rigid)
        return;
      AssertThrow(material.model == "rigid",
                  ExcMessage("body '" + name +
                             "': Rigid motion/Free = true "
                             "needs Model = rigid (it is " +
                             material.model + ")"));
      AssertThrow(rigid_motion.angle == 0. &&
                    rigid_motion.translation.norm() == 0. &&
                    rigid_motion.path.empty(),
                  ExcMessage("body '" + name +
                             "': a free rigid body's motion "
                             "is unknown; set no Translation, Translation "
                             "path or Rotation angle in its Rigid motion"));
    }


    void
    DirichletParameters::declare_parameters(ParameterHandler &prm)
    {
      add_boundary_id(prm, boundary_id);
      prm.add_parameter("Components",
                        components,
                        "Which displacement components are prescribed.",
                        Patterns::Selection("xyz|x|y|z|xy|xz|yz"));
      declare_motion(prm, "boundary", motion);
    }


    void
    DirichletParameters::parse_parameters(ParameterHandler &)
    {
      check_motion(motion);
    }


    void
    TractionParameters::declare_parameters(ParameterHandler &prm)
    {
      add_boundary_id(prm, boundary_id);
      prm.add_parameter("Traction",
                        traction,
                        "Dead traction t0 per unit reference area at load "
                        "factor 1, in stress units" +
                          vector_pattern_doc,
                        vector_pattern());
    }


    void
    OutputParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      prm.add_parameter("Directory",
                        directory,
                        "Folder for VTU/PVD files and the convergence log "
                        "(relative to the current folder); created if "
                        "missing.",
                        Patterns::Anything());
      prm.add_parameter("Base name",
                        base_name,
                        "Files are <base>-NNNN.vtu, <base>.pvd and "
                        "<base>-convergence.csv.",
                        Patterns::Anything());
      prm.add_parameter("Write VTU",
                        write_vtu,
                        "Write a VTU file per converged increment and the "
                        "PVD series.",
                        Patterns::Bool());
      prm.add_parameter("Print timing",
                        print_timing,
                        "Print the wall-clock time summary at the end.",
                        Patterns::Bool());
      prm.add_parameter("Every n steps",
                        every_n_steps,
                        "Write the VTU files of every n-th converged "
                        "increment, or time step where Time integration/"
                        "Output interval is 0 (the first and the last "
                        "state are always written).",
                        Patterns::Integer(1));
      prm.add_parameter("Double precision",
                        double_precision,
                        "Write the VTU values in Float64 instead of Float32 "
                        "(files about twice as large; Float32 limits a "
                        "comparison to 1e-7).",
                        Patterns::Bool());
      prm.add_parameter("Length unit",
                        length_unit,
                        "The unit of length of the input (e.g. mm), written "
                        "beside the fields of the VTU files; empty: none. "
                        "The program itself uses any consistent units.",
                        Patterns::Anything());
      prm.add_parameter("Force unit",
                        force_unit,
                        "The unit of force of the input (e.g. N); with the "
                        "length unit it names the stresses' unit "
                        "(N/mm^2).",
                        Patterns::Anything());
      prm.add_parameter("Old results",
                        old_results,
                        "What to do with files of an earlier run with the "
                        "same base name in the output folder: remove them "
                        "before writing, or refuse to run.",
                        Patterns::Selection("remove|refuse"));
      prm.add_parameter("Checkpoint every n steps",
                        checkpoint_every,
                        "Write <base>-checkpoint.bin (replacing the last "
                        "one) after every n-th converged increment or time "
                        "step; tissue-contact --restart DIR scene.prm "
                        "continues from it. 0: no checkpoints.",
                        Patterns::Integer(0));
      prm.leave_subsection();
    }


    SceneParameters::SceneParameters()
    {
      resize(1, 1, 0, 0, 0);
    }


    void
    SceneParameters::resize(const unsigned int n_bodies,
                            const unsigned int n_dirichlet,
                            const unsigned int n_tractions,
                            const unsigned int n_obstacles,
                            const unsigned int n_pairs)
    {
      bodies.resize(n_bodies);
      dirichlet.resize(n_dirichlet);
      tractions.resize(n_tractions);
      contact.obstacles.resize(n_obstacles);
      contact.pairs.resize(n_pairs);
    }


    void
    SceneParameters::declare_parameters(ParameterHandler &prm)
    {
      // the counts' defaults (the file sets them; the subsections declared
      // below are as many as the vectors hold)
      n_bodies    = 1;
      n_dirichlet = 1;
      n_tractions = 0;
      mesh.declare_parameters(prm);
      prm.enter_subsection("Discretization");
      prm.add_parameter("Polynomial degree",
                        degree,
                        "1: linear tetrahedra (fast); 2: quadratic "
                        "tetrahedra (accurate, no locking in bending).",
                        Patterns::Integer(1, 2));
      prm.add_parameter(
        "Stiffness quadrature",
        stiffness_quadrature,
        "The quadrature rule of the strain energy, its residual and tangent "
        "on P2 elements (P1 elements use one point, exact). full: 14 points, "
        "exact to degree 5. reduced: 6 points, exact to degree 3: still exact "
        "for linear elasticity, the single-rotation element's stiffness, the "
        "mean dilatation's element volume and the body force, an "
        "approximation for the hyperelastic energies (as the four points of "
        "quadratic tetrahedra in most codes), at less than half the assembly "
        "cost; doc/users/choosing.md measures both.",
        Patterns::Selection("full|reduced"));
      prm.add_parameter(
        "DoF numbering",
        dof_numbering,
        "Cuthill-McKee: the mesh's vertices numbered in the Cuthill-McKee "
        "order of their graph and its cells by their lowest vertex, then the "
        "unknowns support point by support point in that order, so that "
        "neighbours lie close in memory (the tangent's rows, the cells' data, "
        "the vectors) and the elastic assembly splits its rows among the "
        "threads; as meshed: the unknowns in the order deal.II distributes "
        "them, cell by cell in the mesh file's order. The same equations; the "
        "sums, the AMG hierarchy's aggregates and so the Newton path differ. "
        "Measured with two threads (doc/theory/02-weak-form-and-"
        "linearization.md sec. 2.3): the full knee in 203 instead of 234 s on "
        "a path as long (its elastic tangent in 13 instead of 28 ms), the "
        "knee-scale tube (prm/knee_tube.prm) in 18-22 instead of 29-32 s; box "
        "meshes and small scenes the same.",
        Patterns::Selection("as meshed|Cuthill-McKee"));
      prm.leave_subsection();

      prm.enter_subsection("Bodies");
      prm.add_parameter("Number of bodies",
                        n_bodies,
                        "How many subsections 'Body 0', 'Body 1', ... "
                        "follow, one per material id of the mesh (1..64).",
                        Patterns::Integer(1, 64));
      for (unsigned int i = 0; i < bodies.size(); ++i)
        {
          prm.enter_subsection("Body " + std::to_string(i));
          bodies[i].declare_parameters(prm);
          prm.leave_subsection();
        }
      prm.leave_subsection();

      prm.enter_subsection("Boundary conditions");
      prm.add_parameter("Number of Dirichlet conditions",
                        n_dirichlet,
                        "How many subsections 'Dirichlet 0', ... follow "
                        "(0..64).",
                        Patterns::Integer(0, 64));
      prm.add_parameter("Number of tractions",
                        n_tractions,
                        "How many subsections 'Traction 0', ... follow "
                        "(0..64).",
                        Patterns::Integer(0, 64));
      for (unsigned int i = 0; i < dirichlet.size(); ++i)
        {
          prm.enter_subsection("Dirichlet " + std::to_string(i));
          dirichlet[i].declare_parameters(prm);
          prm.leave_subsection();
        }
      for (unsigned int i = 0; i < tractions.size(); ++i)
        {
          prm.enter_subsection("Traction " + std::to_string(i));
          tractions[i].declare_parameters(prm);
          prm.leave_subsection();
        }
      prm.leave_subsection();

      prm.enter_subsection("Loads");
      prm.add_parameter("Gravity",
                        gravity,
                        "Body force per unit mass g at load factor 1 "
                        "(acceleration units; multiplied by each body's "
                        "density)" +
                          vector_pattern_doc,
                        vector_pattern());
      prm.leave_subsection();

      contact.declare_parameters(prm);
      solver.declare_parameters(prm);
      time_integration.declare_parameters(prm);
      output.declare_parameters(prm);
    }


    namespace
    {
      /** Text for a Markdown table cell: one line, '|' escaped. */
      std::string
      cell(std::string s)
      {
        for (char &c : s)
          if (c == '\n' || c == '\t')
            c = ' ';
        std::string out;
        for (const char c : s)
          out += (c == '|' ? std::string("\\|") : std::string(1, c));
        const auto first = out.find_first_not_of(' ');
        return first == std::string::npos ? "" : out.substr(first);
      }

      /** One table per subsection that holds entries, depth first. */
      void
      write_tables(const boost::property_tree::ptree &node,
                   const std::string                 &path,
                   std::ostream                      &out)
      {
        std::vector<const boost::property_tree::ptree *> entries;
        std::vector<std::string>                         names;
        for (const auto &[name, child] : node)
          if (child.count("value") > 0 && child.count("documentation") > 0)
            {
              entries.push_back(&child);
              names.push_back(demangle_xml_name(name));
            }
        if (!entries.empty())
          {
            out << "\n## " << (path.empty() ? "(top level)" : path) << "\n\n"
                << "| entry | default | allowed values | description |\n"
                << "| --- | --- | --- | --- |\n";
            for (unsigned int i = 0; i < entries.size(); ++i)
              out << "| `" << names[i] << "` | `"
                  << cell(entries[i]->get<std::string>("default_value"))
                  << "` | "
                  << cell(entries[i]->get<std::string>("pattern_description"))
                  << " | "
                  << cell(entries[i]->get<std::string>("documentation"))
                  << " |\n";
          }
        for (const auto &[name, child] : node)
          if (!(child.count("value") > 0 && child.count("documentation") > 0))
            write_tables(child,
                         path.empty() ? demangle_xml_name(name) :
                                        path + " / " + demangle_xml_name(name),
                         out);
      }
    } // namespace


    void
    SceneParameters::print_markdown(ParameterHandler &prm, std::ostream &out)
    {
      std::stringstream xml;
      prm.print_parameters(xml, ParameterHandler::XML);
      boost::property_tree::ptree tree;
      boost::property_tree::read_xml(xml, tree);
      out << "# Parameter reference\n\n"
          << "Every entry of a scene's parameter file (`prm/*.prm`), with its "
             "default, the values it accepts and what it does. Numbered "
             "subsections (`Body 0`, `Dirichlet 0`, `Pair 0`, ...) are shown "
             "once and repeat with their count. The program uses any "
             "consistent set of units (e.g. mm, N, MPa = N/mm^2, t/mm^3 for "
             "the density); `Output/Length unit` and `Force unit` only label "
             "the output.\n\n"
          << "Generated by `tissue-contact --print-parameters=markdown` "
             "(also `=json`, and plain `--print-parameters` for a commented "
             "parameter file); the test `scene/print_parameters` fails when "
             "this page differs from what the program prints.\n";
      write_tables(tree.get_child("ParameterHandler"), "", out);
    }


    void
    SceneParameters::print_reference(std::ostream      &out,
                                     const std::string &format)
    {
      SceneParameters p;
      p.resize(1, 1, 1, 1, 1);
      ParameterHandler prm;
      p.declare_parameters(prm);
      if (format == "prm")
        prm.print_parameters(out, ParameterHandler::PRM);
      else if (format == "json")
        prm.print_parameters(out, ParameterHandler::JSON);
      else if (format == "markdown")
        print_markdown(prm, out);
      else
        AssertThrow(false,
                    ExcMessage("unknown format '" + format +
                               "' of --print-parameters: prm, json or "
                               "markdown"));
    }


    void
    SceneParameters::parse_parameters(ParameterHandler  &prm,
                                      const std::string &dir)
    {
      AssertThrow(!output.base_name.empty() &&
                    output.base_name.find('/') == std::string::npos,
                  ExcMessage("Output: Base name '" + output.base_name +
                             "' must be a file name (not empty, no '/'); "
                             "the folder is Output/Directory"));
      mesh.parse_parameters(prm, dir);
      for (auto &b : bodies)
        b.parse_parameters(prm);
      for (auto &d : dirichlet)
        d.parse_parameters(prm);
      contact.body_of_material.clear();
      for (const auto &b : bodies)
        if (b.contact_body >= 0 &&
            static_cast<types::material_id>(b.contact_body) != b.id)
          {
            bool known = false;
            for (const auto &other : bodies)
              known =
                known ||
                (other.id == static_cast<types::material_id>(b.contact_body) &&
                 other.contact_body < 0);
            AssertThrow(known,
                        ExcMessage("body '" + b.name + "': Contact body " +
                                   std::to_string(b.contact_body) +
                                   " is not the Material id of a body that is "
                                   "its own contact body"));
            contact.body_of_material[b.id] = b.contact_body;
          }
      contact.parse_parameters(prm);
      solver.parse_parameters(prm);
      time_integration.parse_parameters(prm);
    }


    SceneParameters
    SceneParameters::parse_text(const std::string &text,
                                const std::string &name,
                                const std::string &directory)
    {
      // first pass: the numbers of subsections (the rest is skipped)
      SceneParameters counts;
      {
        ParameterHandler prm;
        counts.declare_parameters(prm);
        std::istringstream in(text);
        prm.parse_input(in, name, "", /*skip_undefined=*/true);
      }
      // second pass, strict: every subsection declared, every entry known
      SceneParameters p;
      p.resize(counts.n_bodies,
               counts.n_dirichlet,
               counts.n_tractions,
               counts.contact.n_obstacles,
               counts.contact.n_pairs);
      ParameterHandler prm;
      p.declare_parameters(prm);
      std::istringstream in(text);
      prm.parse_input(in, name);
      p.parse_parameters(prm, directory);
      std::ostringstream effective;
      effective << "# The effective parameters of " << name
                << ": every entry, as read or by default\n";
      prm.print_parameters(effective, ParameterHandler::ShortPRM);
      p.effective_parameters = effective.str();
      return p;
    }


    SceneParameters
    SceneParameters::from_file(const std::string &filename)
    {
      AssertThrow(!std::filesystem::is_directory(filename),
                  ExcMessage("'" + filename +
                             "' is a folder, not a parameter file: give a "
                             ".prm file (see prm/)"));
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
