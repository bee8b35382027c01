#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/materials/material_factory.h>
#include <tissue_contact/scene/scene.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>

#include <unistd.h>

#include <deque>
#include <filesystem>
#include <fstream>
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


      /** Mesh the gmsh geometry @p geo with `gmsh -3 @p options` into a
       * temporary .msh file (format 2.2) and return its name; an error
       * quoting gmsh's last lines if gmsh is missing or fails. */
      std::string
      mesh_geometry(const std::string &geo, const std::string &options)
      {
        namespace fs = std::filesystem;
        const std::string stem =
          (fs::temp_directory_path() /
           ("tissue-contact-" + std::to_string(::getpid())))
            .string();
        const std::string msh = stem + ".msh", log = stem + ".log";
        const std::string cmd = "gmsh -3 -format msh22 " + options + " '" +
                                geo + "' -o '" + msh + "' > '" + log + "' 2>&1";
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
                    ExcMessage("gmsh could not mesh the geometry '" + geo +
                               "' (Mesh: Source = geo; is gmsh installed? "
                               "command: " +
                               cmd + "); its last output:" + tail));
        return msh;
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
          const std::string msh =
            m.source == "geo" ? mesh_geometry(m.file, m.gmsh_options) : m.file;
          GridIn<3> grid_in;
          grid_in.attach_triangulation(triangulation);
          std::ifstream in(msh);
          try
            {
              grid_in.read_msh(in);
            }
          catch (const std::exception &e)
            {
              AssertThrow(false,
                          ExcMessage(
                            "cannot read mesh file '" + m.file +
                            "' as a gmsh .msh file: " + error_message(e)));
            }
          if (m.source == "geo")
            std::filesystem::remove(msh);
        }
      if (m.scale != 1.)
        GridTools::scale(m.scale, triangulation);
      if (m.distortion > 0.)
        GridTools::distort_random(m.distortion, triangulation, true, 20261122);
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
        data[parameters.bodies[i].id] = {
          materials[i].get(),
          parameters.bodies[i].density,
          !parameters.bodies[i].prescribed_rigid()};
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
