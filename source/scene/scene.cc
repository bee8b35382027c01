#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/base/mesh_order.h>
#include <tissue_contact/materials/material_factory.h>
#include <tissue_contact/scene/scene.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>

#include <unistd.h>

#include <cmath>
#include <deque>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace TissueContact
{
  namespace Scene
  {
    Scene::Scene(const SceneParameters &p)
      : parameters(p)
    {
      std::set<types::material_id> ids;
      for (const auto &b : parameters.bodies)
        {
          AssertThrow(ids.insert(b.id).second,
                      ExcMessage("two bodies use material id " +
                                 std::to_string(b.id)));
          try
            {
              materials.push_back(Materials::create_material(b.material));
            }
          catch (const ExceptionBase &e)
            {
              AssertThrow(false,
                          ExcMessage("body '" + b.name + "' (material id " +
                                     std::to_string(b.id) +
                                     "): " + error_message(e)));
            }
        }
      create_mesh();
      check_mesh();
    }


    namespace
    {
      /** Call @p f(DoF, component) once for every DoF of the cells of
       * material id @p id (a rigid body's DoFs). */
      template <typename F>
      void
      for_each_body_dof(const Discretization    &disc,
                        const types::material_id id,
                        const F                 &f)
      {
        std::vector<types::global_dof_index> dofs(disc.fe.n_dofs_per_cell());
        std::set<types::global_dof_index>    seen;
        for (const auto &cell : disc.dof_handler.active_cell_iterators())
          if (cell->material_id() == id)
            {
              cell->get_dof_indices(dofs);
              for (unsigned int k = 0; k < dofs.size(); ++k)
                if (seen.insert(dofs[k]).second)
                  f(dofs[k], disc.fe.system_to_component_index(k).first);
            }
      }


      /** Run `gmsh @p options @p geo` into a temporary .msh file (format
       * 2.2) and return its name: `-3 ...` meshes a geometry, `-0`
       * converts a mesh of another format; an error quoting gmsh's last
       * lines if gmsh is missing or fails. */
      std::string
      gmsh_to_msh(const std::string &geo, const std::string &options)
      {
        namespace fs = std::filesystem;
        const std::string stem =
          (fs::temp_directory_path() /
           ("tissue-contact-" + std::to_string(::getpid())))
            .string();
        const std::string msh = stem + ".msh", log = stem + ".log";
        const std::string cmd = "gmsh -format msh22 " + options + " '" + geo +
                                "' -o '" + msh + "' > '" + log + "' 2>&1";
        const int   status = std::system(cmd.c_str());
        const bool  ok     = status == 0 && fs::exists(msh);
        std::string tail;
        {
          std::ifstream           in(log);
          std::deque<std::string> lines;
          for (std::string line; std::getline(in, line);)
            {
              lines.push_back(line);
              if (lines.size() > 5)
                lines.pop_front();
            }
          for (const auto &line : lines)
            tail += "\n  " + line;
        }
        fs::remove(log);
        AssertThrow(ok,
                    ExcMessage("gmsh could not " +
                               std::string(options.rfind("-0", 0) == 0 ?
                                             "convert the mesh '" :
                                             "mesh the geometry '") +
                               geo + "' (is gmsh installed? command: " + cmd +
                               "); its last output:" + tail));
        return msh;
      }

      /** What is wrong with the gmsh file @p file before its parser sees
       * it (empty, binary, of a version the reader does not know,
       * truncated), or "" if nothing. */
      std::string
      gmsh_file_problem(const std::string &file)
      {
        std::ifstream in(file, std::ios::binary);
        std::string   first, format;
        std::getline(in, first);
        std::getline(in, format);
        if (!first.empty() && first.back() == '\r')
          first.pop_back();
        if (first != "$MeshFormat")
          return "it does not start with $MeshFormat: not a gmsh .msh file "
                 "(or one in gmsh's old format 1)";
        std::istringstream f(format);
        std::string        version;
        int                file_type = -1;
        f >> version >> file_type;
        if (version.empty() ||
            version.find_first_not_of("0123456789.") != std::string::npos)
          return "its $MeshFormat section holds '" + format +
                 "' instead of a version, file type and data size";
        if (version.rfind("2.", 0) != 0 && version.rfind("4.", 0) != 0)
          return "its format version is " + version +
                 "; this program reads versions 2 and 4 (gmsh -format msh22 "
                 "or msh41)";
        if (file_type != 0)
          return "it is a binary file; save it as ASCII (gmsh -bin 0, or "
                 "File > Export with 'Save all' and ASCII)";
        // the last kilobytes must close the element section
        in.seekg(0, std::ios::end);
        const std::streamoff size = in.tellg();
        const std::streamoff tail = std::min<std::streamoff>(size, 4096);
        std::string          end(tail, '\0');
        in.seekg(size - tail);
        in.read(&end[0], tail);
        if (end.find("$EndElements") == std::string::npos)
          return "it is truncated: it ends before $EndElements (an "
                 "interrupted download or copy?)";
        // coordinates the parser would stop at with a misleading message
        in.clear();
        in.seekg(0);
        bool in_nodes = false;
        for (std::string line; std::getline(in, line);)
          {
            if (line.rfind("$Nodes", 0) == 0)
              in_nodes = true;
            else if (line.rfind("$EndNodes", 0) == 0)
              break;
            else if (in_nodes)
              for (char &c : line)
                c = std::tolower(c);
            if (in_nodes && (line.find("nan") != std::string::npos ||
                             line.find("inf") != std::string::npos))
              return "a node has a NaN or infinite coordinate (line '" + line +
                     "' of the $Nodes section)";
          }
        return "";
      }


      /** Read the mesh file @p file, its format chosen by the suffix (.msh
       * gmsh, .unv I-DEAS, .vtk legacy VTK; .inp and .vtu are refused
       * with the reason), into @p triangulation; every problem named. */
      void
      read_mesh_file(const std::string &file, Triangulation<3> &triangulation)
      {
        namespace fs = std::filesystem;
        AssertThrow(fs::exists(file) && !fs::is_directory(file) &&
                      std::ifstream(file).good(),
                    ExcMessage("mesh file '" + file +
                               "' does not exist or cannot be read"));
        AssertThrow(fs::file_size(file) > 0,
                    ExcMessage("the mesh file '" + file + "' is empty"));
        std::string suffix = fs::path(file).extension().string();
        for (char &c : suffix)
          c = std::tolower(c);
        // deal.II 9.4 reads tetrahedra from gmsh files only (its Abaqus,
        // UNV and VTK readers take hexahedra): I-DEAS and legacy VTK files
        // are converted by gmsh, which keeps UNV's groups as material and
        // boundary ids (VTK has none: every id is 0)
        if (suffix == ".unv" || suffix == ".vtk")
          {
            const std::string msh = gmsh_to_msh(file, "-0");
            try
              {
                read_mesh_file(msh, triangulation);
              }
            catch (...)
              {
                fs::remove(msh);
                throw;
              }
            fs::remove(msh);
            return;
          }
        AssertThrow(suffix != ".inp" && suffix != ".vtu",
                    ExcMessage("cannot read the mesh file '" + file + "': " +
                               (suffix == ".inp" ?
                                  "Abaqus .inp files of tetrahedra are read "
                                  "neither by deal.II 9.4 (hexahedra only) "
                                  "nor by gmsh 4.8" :
                                  "deal.II 9.4 reads only the .vtu files it "
                                  "wrote itself") +
                               "; export the mesh as gmsh .msh (versions 2 "
                               "or 4), I-DEAS .unv or legacy .vtk"));
        AssertThrow(suffix == ".msh",
                    ExcMessage("the mesh file '" + file + "' has the suffix '" +
                               suffix +
                               "', which names no format this program "
                               "reads: .msh (gmsh), .unv (I-DEAS) or .vtk "
                               "(legacy VTK)"));
        const std::string problem = gmsh_file_problem(file);
        AssertThrow(problem.empty(),
                    ExcMessage("cannot read the mesh file '" + file +
                               "': " + problem));
        GridIn<3> grid_in;
        grid_in.attach_triangulation(triangulation);
        std::ifstream in(file);
        try
          {
            grid_in.read_msh(in);
          }
        catch (const std::bad_alloc &)
          {
            AssertThrow(false,
                        ExcMessage("the mesh in '" + file +
                                   "' needs more memory than this machine "
                                   "has (or its node or element count is "
                                   "corrupt)"));
          }
        catch (const std::length_error &)
          {
            AssertThrow(false,
                        ExcMessage("the mesh in '" + file +
                                   "' declares more nodes or elements than "
                                   "can be stored (a corrupt count?)"));
          }
        catch (const std::exception &e)
          {
            AssertThrow(false,
                        ExcMessage(
                          "cannot read the mesh file '" + file +
                          "' as a gmsh .msh file: " + error_message(e)));
          }
        const auto &vertices = triangulation.get_vertices();
        for (unsigned int v = 0; v < vertices.size(); ++v)
          for (unsigned int d = 0; d < 3; ++d)
            AssertThrow(
              std::isfinite(vertices[v][d]) && std::abs(vertices[v][d]) < 1e100,
              ExcMessage("the mesh file '" + file + "' has " +
                         (std::isfinite(vertices[v][d]) ?
                            "a coordinate out of range (" +
                              Utilities::to_string(vertices[v][d]) + ")" :
                            "a NaN or infinite coordinate") +
                         " at vertex " + std::to_string(v)));
      }
    } // namespace


    void
    Scene::create_mesh()
    {
      const MeshParameters &m = parameters.mesh;
      if (m.source == "box")
        {
          GridGenerator::subdivided_hyper_rectangle_with_simplices(
            triangulation, m.subdivisions, m.lower, m.upper);
          // boundary ids 0..5 on the faces x-, x+, y-, y+, z-, z+ (deal.II
          // 9.4 cannot colorize simplex boxes)
          for (const auto &cell : triangulation.active_cell_iterators())
            for (const auto &face : cell->face_iterators())
              if (face->at_boundary())
                {
                  const Point<3> c = face->center();
                  for (unsigned int d = 0; d < 3; ++d)
                    {
                      const double tol = 1e-8 * (m.upper[d] - m.lower[d]);
                      if (std::abs(c[d] - m.lower[d]) < tol)
                        face->set_boundary_id(2 * d);
                      else if (std::abs(c[d] - m.upper[d]) < tol)
                        face->set_boundary_id(2 * d + 1);
                    }
                }
        }
      else
        {
          AssertThrow(std::ifstream(m.file).good(),
                      ExcMessage("mesh file '" + m.file +
                                 "' does not exist or cannot be read"));
          if (m.source == "geo")
            {
              const std::string msh =
                gmsh_to_msh(m.file, "-3 " + m.gmsh_options);
              try
                {
                  read_mesh_file(msh, triangulation);
                }
              catch (...)
                {
                  std::filesystem::remove(msh);
                  throw;
                }
              std::filesystem::remove(msh);
            }
          else
            read_mesh_file(m.file, triangulation);
        }
      if (m.scale != 1.)
        GridTools::scale(m.scale, triangulation);
      for (const auto &x : triangulation.get_vertices())
        AssertThrow(x.norm() < 1e100,
                    ExcMessage("the mesh's coordinates are out of range "
                               "after Mesh/Scale = " +
                               Utilities::to_string(m.scale) + " (" +
                               Utilities::to_string(x.norm()) +
                               "): use a scale that keeps them below 1e100"));
      if (m.distortion > 0.)
        GridTools::distort_random(m.distortion, triangulation, true, 20261122);
      // after the distortion, which moves the vertices in their order: the
      // same geometry either way
      if (parameters.dof_numbering == "Cuthill-McKee")
        order_mesh_by_cuthill_mckee(triangulation);
    }


    void
    Scene::check_mesh() const
    {
      AssertThrow(triangulation.n_active_cells() > 0,
                  ExcMessage("the mesh has no cells"));
      std::set<types::material_id> body_ids;
      for (const auto &b : parameters.bodies)
        body_ids.insert(b.id);
      std::set<types::material_id> mesh_ids;
      std::set<types::boundary_id> boundary_ids;
      for (const auto &cell : triangulation.active_cell_iterators())
        {
          AssertThrow(cell->reference_cell() == ReferenceCells::Tetrahedron,
                      ExcMessage("the mesh has a cell that is not a "
                                 "tetrahedron (cell " +
                                 std::to_string(cell->active_cell_index()) +
                                 "); only tetrahedral meshes are supported"));
          mesh_ids.insert(cell->material_id());
          AssertThrow(body_ids.count(cell->material_id()) > 0,
                      ExcMessage("the mesh has cells with material id " +
                                 std::to_string(cell->material_id()) +
                                 " but no body in the parameter file uses it; "
                                 "add a 'Body' subsection with this Material "
                                 "id"));
          const Tensor<1, 3> e1     = cell->vertex(1) - cell->vertex(0);
          const Tensor<1, 3> e2     = cell->vertex(2) - cell->vertex(0);
          const Tensor<1, 3> e3     = cell->vertex(3) - cell->vertex(0);
          const double       volume = (e1 * cross_product_3d(e2, e3)) / 6.;
          double             h      = 0.;
          for (unsigned int l = 0; l < cell->n_lines(); ++l)
            h = std::max(h, cell->line(l)->diameter());
          std::ostringstream where;
          where << "cell " << cell->active_cell_index() << " (material id "
                << int(cell->material_id()) << ", first vertex "
                << cell->vertex(0) << ")";
          AssertThrow(volume > 0. || std::abs(volume) <= 1e-10 * h * h * h,
                      ExcMessage(
                        "the mesh has an inverted tetrahedron: " + where.str() +
                        " has negative volume; fix the element's "
                        "node order in the mesh"));
          AssertThrow(volume > 1e-10 * h * h * h,
                      ExcMessage("the mesh has a degenerate (flat) "
                                 "tetrahedron: " +
                                 where.str() + "; remesh"));
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              boundary_ids.insert(cell->face(f)->boundary_id());
        }
      for (const auto &b : parameters.bodies)
        AssertThrow(mesh_ids.count(b.id) > 0,
                    ExcMessage("body '" + b.name + "' uses material id " +
                               std::to_string(b.id) +
                               ", which no cell of the mesh has"));
      const auto check_boundary = [&](const types::boundary_id id,
                                      const std::string       &what) {
        std::ostringstream present;
        for (const auto i : boundary_ids)
          present << " " << int(i);
        AssertThrow(boundary_ids.count(id) > 0,
                    ExcMessage(what + ": boundary id " + std::to_string(id) +
                               " does not occur in the mesh (its boundary "
                               "ids are:" +
                               present.str() + ")"));
      };
      for (unsigned int i = 0; i < parameters.dirichlet.size(); ++i)
        check_boundary(parameters.dirichlet[i].boundary_id,
                       "Dirichlet " + std::to_string(i));
      for (unsigned int i = 0; i < parameters.tractions.size(); ++i)
        check_boundary(parameters.tractions[i].boundary_id,
                       "Traction " + std::to_string(i));
      for (const auto id : parameters.contact.surfaces)
        check_boundary(id, "Contact surfaces");
      for (unsigned int i = 0; i < parameters.contact.pairs.size(); ++i)
        for (const auto id : {parameters.contact.pairs[i].surface_body,
                              parameters.contact.pairs[i].volume_body})
          AssertThrow(mesh_ids.count(id) > 0,
                      ExcMessage("Contact pair " + std::to_string(i) +
                                 " names material id " + std::to_string(id) +
                                 ", which no cell of the mesh has"));
      for (unsigned int i = 0; i < parameters.contact.obstacles.size(); ++i)
        for (const auto id : parameters.contact.obstacles[i].bodies)
          AssertThrow(mesh_ids.count(id) > 0,
                      ExcMessage("Obstacle " + std::to_string(i) +
                                 ": Bodies names material id " +
                                 std::to_string(id) +
                                 ", which no cell of the mesh has"));
    }


    std::map<types::material_id, Elasticity::BodyData>
    Scene::body_data() const
    {
      std::map<types::material_id, Elasticity::BodyData> data;
      for (unsigned int i = 0; i < parameters.bodies.size(); ++i)
        {
          const auto &b    = parameters.bodies[i];
          using VolumeTerm = Elasticity::BodyData::VolumeTerm;
          data[b.id]       = {materials[i].get(),
                              b.density,
                              !b.prescribed_rigid(),
                        b.material.nodal_volume() ?
                                VolumeTerm::nodal_average :
                                (b.material.element_volume() ?
                                   VolumeTerm::element_average :
                                   VolumeTerm::in_material),
                              b.material.bulk_modulus,
                              b.material.single_rotation()};
        }
      return data;
    }


    Elasticity::DeadLoads
    Scene::dead_loads() const
    {
      Elasticity::DeadLoads loads;
      loads.gravity = parameters.gravity;
      for (const auto &t : parameters.tractions)
        loads.tractions[t.boundary_id] += t.traction;
      return loads;
    }


    std::vector<PrescribedDof>
    Scene::prescribed_dofs(const Discretization &disc) const
    {
      const std::vector<Point<3>>          X  = disc.support_points();
      const auto                          &fe = disc.fe;
      std::vector<PrescribedDof>           result;
      std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());

      for (const auto &d : parameters.dirichlet)
        {
          const bool use[3] = {d.components.find('x') != std::string::npos,
                               d.components.find('y') != std::string::npos,
                               d.components.find('z') != std::string::npos};
          std::set<types::global_dof_index> seen;
          for (const auto &cell : disc.dof_handler.active_cell_iterators())
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  cell->face(f)->boundary_id() == d.boundary_id)
                {
                  cell->face(f)->get_dof_indices(face_dofs);
                  for (unsigned int k = 0; k < face_dofs.size(); ++k)
                    {
                      const unsigned int c =
                        fe.face_system_to_component_index(k, f).first;
                      if (use[c] && seen.insert(face_dofs[k]).second)
                        result.push_back(
                          {face_dofs[k], c, X[face_dofs[k]], &d.motion});
                    }
                }
        }

      for (const auto &b : parameters.bodies)
        if (b.prescribed_rigid())
          for_each_body_dof(disc,
                            b.id,
                            [&](const types::global_dof_index i,
                                const unsigned int            c) {
                              result.push_back({i, c, X[i], &b.rigid_motion});
                            });
      return result;
    }


    std::vector<Rigid::FreeRigidBodies::Body>
    Scene::free_rigid_bodies(const Discretization &disc) const
    {
      const std::vector<Point<3>>               X = disc.support_points();
      std::vector<Rigid::FreeRigidBodies::Body> result;
      for (const auto &b : parameters.bodies)
        if (b.free_rigid)
          {
            Rigid::FreeRigidBodies::Body body;
            body.name = b.name;
            for_each_body_dof(disc,
                              b.id,
                              [&](const types::global_dof_index i,
                                  const unsigned int            c) {
                                body.dofs.push_back(i);
                                body.components.push_back(c);
                                body.X.push_back(X[i]);
                              });
            result.push_back(body);
          }
      return result;
    }
  } // namespace Scene
} // namespace TissueContact
