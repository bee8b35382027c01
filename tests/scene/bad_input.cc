// Bad input gives one clear error naming what is wrong, never a crash:
// a missing, broken or non-tetrahedral-valid mesh, unknown or malformed prm
// entries, an unknown material model, a negative stiffness, ids that do not
// match the mesh, and a diverging solve (whose converged increments are kept
// on disk).

#include "../tests.h"

#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/simulation/static_simulation.h>

#include <fstream>
#include <sstream>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

namespace
{
  const std::string quiet = "subsection Output\n set Print timing = false\n"
                            " set Directory = bad-output\nend\n";

  void
  run(const std::string &name, const std::string &prm)
  {
    std::ostringstream screen;
    try
      {
        StaticSimulation sim(Scene::SceneParameters::from_string(quiet + prm),
                             screen);
        sim.run();
        deallog << name << ": no error" << std::endl;
      }
    catch (const std::exception &e)
      {
        deallog << name << ": error: " << error_message(e) << std::endl;
      }
  }

  void
  write_tet_mesh(const std::string &file,
                 const std::string &fourth_node,
                 const std::string &node_order)
  {
    std::ofstream out(file);
    out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n"
           "1 0 0 0\n2 1 0 0\n3 0 1 0\n4 "
        << fourth_node << "\n$EndNodes\n$Elements\n1\n1 4 2 1 1 " << node_order
        << "\n$EndElements\n";
  }

  std::string
  mesh_file(const std::string &file)
  {
    return "subsection Mesh\n set Source = file\n set File = " + file +
           "\nend\nsubsection Bodies\n subsection Body 0\n"
           "  set Material id = 1\n end\nend\n"
           "subsection Boundary conditions\n"
           " set Number of Dirichlet conditions = 0\nend\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  run("missing mesh file", mesh_file("no_such_mesh.msh"));

  std::ofstream("broken.msh") << "$MeshFormat\nthis is not a mesh\n";
  run("broken mesh file", mesh_file("broken.msh"));

  // a tetrahedron with its node order reversed in the file: deal.II's reader
  // reorients such cells, so the mesh is valid with positive volume
  write_tet_mesh("good.msh", "0 0 1", "1 2 3 4");
  write_tet_mesh("reversed.msh", "0 0 1", "1 3 2 4");
  for (const std::string file : {"good.msh", "reversed.msh"})
    {
      std::ostringstream screen;
      StaticSimulation   sim(Scene::SceneParameters::from_string(quiet +
                                                               mesh_file(file)),
                           screen);
      const auto cell = sim.problem().get_scene().triangulation.begin_active();
      deallog << file << ": read, tetrahedron volume "
              << ((cell->vertex(1) - cell->vertex(0)) *
                  cross_product_3d(cell->vertex(2) - cell->vertex(0),
                                   cell->vertex(3) - cell->vertex(0))) /
                   6.
              << std::endl;
    }
  write_tet_mesh("flat.msh", "0.3 0.3 0", "1 2 3 4");
  run("degenerate element", mesh_file("flat.msh"));

  run(
    "unknown material model",
    "subsection Bodies\n subsection Body 0\n  set Model = Ogden\n end\nend\n");
  run("negative stiffness",
      "subsection Bodies\n subsection Body 0\n  set Mu = -2\n end\nend\n");
  run("Mooney-Rivlin without energy barrier",
      "subsection Bodies\n subsection Body 0\n  set Model = Mooney-Rivlin\n"
      "  set C1 = 1\n  set C2 = 1\n  set a = -2.5\n end\nend\n");
  run("unknown entry", "subsection Newton\n set Maximum iteration = 3\nend\n");
  run("malformed value",
      "subsection Discretization\n set Polynomial degree = three\nend\n");
  run("degree out of range",
      "subsection Discretization\n set Polynomial degree = 3\nend\n");
  run("missing body for a material id",
      "subsection Mesh\n set Source = file\n"
      " set File = " SOURCE_DIR "/layered_block_v2.msh\nend\n"
      "subsection Bodies\n subsection Body 0\n  set Material id = 1\n"
      " end\nend\nsubsection Boundary conditions\n"
      " subsection Dirichlet 0\n  set Boundary id = 1\n end\nend\n");
  run("boundary id not in the mesh",
      "subsection Boundary conditions\n subsection Dirichlet 0\n"
      "  set Boundary id = 9\n end\nend\n");
  run("two bodies with one material id",
      "subsection Bodies\n set Number of bodies = 2\n"
      " subsection Body 0\n end\n subsection Body 1\n end\nend\n");
  run("contact body that is no body",
      "subsection Bodies\n subsection Body 0\n  set Contact body = 5\n end\n"
      "end\n");
  run("translation path of one waypoint",
      "subsection Boundary conditions\n subsection Dirichlet 0\n"
      "  set Translation path = 0, 0, 0.1\n end\nend\n");
  run("translation and translation path",
      "subsection Boundary conditions\n subsection Dirichlet 0\n"
      "  set Translation = 0, 0, 0.1\n"
      "  set Translation path = 0, 0, 0; 0, 0, 0.1\n end\nend\n");
  run("waypoint of two numbers",
      "subsection Boundary conditions\n subsection Dirichlet 0\n"
      "  set Translation path = 0, 0, 0; 0, 0.1\n end\nend\n");
  run("fiber direction that is not a formula",
      "subsection Bodies\n subsection Body 0\n  subsection Fiber\n"
      "   set Enabled = true\n   set Direction = 1; 0\n  end\n end\nend\n");

  // a load far beyond what the soft cube can carry: elements invert, the
  // increment is cut back until it falls below the minimum
  run("diverging solve",
      "subsection Bodies\n subsection Body 0\n  set Mu = 1\n"
      "  set Lambda = 1\n end\nend\n"
      "subsection Mesh\n set Box subdivisions = 2, 2, 2\nend\n"
      "subsection Boundary conditions\n subsection Dirichlet 0\n"
      "  set Boundary id = 4\n end\nend\n"
      "subsection Loads\n set Gravity = 0, 0, -1e4\nend\n"
      "subsection Load stepping\n set Initial increment = 0.5\n"
      " set Minimum increment = 1e-4\nend\n");
  std::ifstream pvd("bad-output/solution.pvd");
  std::string   line;
  unsigned int  records = 0;
  while (std::getline(pvd, line))
    records += (line.find("<DataSet") != std::string::npos);
  deallog << "files kept after the failure: " << records
          << " states in bad-output/solution.pvd" << std::endl;
}
