// Bad input gives one clear error naming what is wrong, never a crash:
// a missing, broken or non-tetrahedral-valid mesh, unknown or malformed prm
// entries, an unknown material model, a negative stiffness, ids that do not
// match the mesh, and a diverging solve (whose converged increments are kept
// on disk). Then a corpus of broken meshes (empty, binary, other versions,
// truncated, NaN or huge coordinates, a corrupt node count, formats that
// cannot hold tetrahedra here), values out of range (zero penalties and
// radii, overflowing moduli and exponents, a tolerance that accepts the
// unloaded state, a massless dynamic body), contact on a body with no
// material depth, a KINSOL solve that stops short, a time step that fails
// below its minimum, and broken checkpoints and output folders.

#include "../tests.h"

#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/simulation/checkpoint.h>
#include <tissue_contact/simulation/dynamic_simulation.h>
#include <tissue_contact/simulation/static_simulation.h>

#include <filesystem>
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
        std::istringstream lines(screen.str());
        for (std::string line; std::getline(lines, line);)
          if (line.rfind("  warning: ", 0) == 0)
            deallog << name << ":" << line.substr(1) << std::endl;
      }
    catch (const std::exception &e)
      {
        deallog << name << ": error: " << error_message(e) << std::endl;
      }
  }

  void
  run_dynamic(const std::string &name, const std::string &prm)
  {
    std::ostringstream screen;
    try
      {
        DynamicSimulation sim(Scene::SceneParameters::from_string(quiet + prm),
                              screen);
        sim.run();
        deallog << name << ": no error" << std::endl;
      }
    catch (const std::exception &e)
      {
        deallog << name << ": error: " << error_message(e) << std::endl;
      }
  }

  /** A one-tetrahedron gmsh 2.2 file with @p format_line and @p nodes
   * (the $Nodes section's body), cut after @p keep characters if given. */
  void
  write_msh(const std::string &file,
            const std::string &format_line,
            const std::string &nodes,
            const std::size_t  keep = std::string::npos)
  {
    const std::string text =
      "$MeshFormat\n" + format_line + "\n$EndMeshFormat\n$Nodes\n" + nodes +
      "$EndNodes\n$Elements\n1\n1 4 2 1 1 1 2 3 4\n$EndElements\n";
    std::ofstream(file) << text.substr(0, keep);
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
  run("uncoupled form of a model that has none",
      "subsection Bodies\n subsection Body 0\n"
      "  set Model = Saint Venant-Kirchhoff\n  set Formulation = uncoupled\n"
      " end\nend\n");
  run("uncoupled Mooney-Rivlin without bulk modulus",
      "subsection Bodies\n subsection Body 0\n  set Model = Mooney-Rivlin\n"
      "  set Formulation = uncoupled\n  set Bulk modulus = 0\n end\nend\n");
  run("volume term at the vertices of a coupled form",
      "subsection Bodies\n subsection Body 0\n"
      "  set Volumetric term = nodal average\n end\nend\n");
  run("volume term at the vertices of P2 elements",
      "subsection Discretization\n set Polynomial degree = 2\nend\n"
      "subsection Bodies\n subsection Body 0\n  set Formulation = uncoupled\n"
      "  set Volumetric term = nodal average\n end\nend\n");
  run("single rotation of a model that is not corotated",
      "subsection Bodies\n subsection Body 0\n  set Rotation = element\n"
      " end\nend\n");
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

  // --- broken meshes
  const std::string tet = "4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n";
  std::ofstream("empty.msh");
  run("empty mesh file", mesh_file("empty.msh"));
  write_msh("binary.msh", "2.2 1 8", tet);
  run("binary gmsh file", mesh_file("binary.msh"));
  write_msh("version3.msh", "3.0 0 8", tet);
  run("gmsh format version 3", mesh_file("version3.msh"));
  std::ofstream("version1.msh") << "$NOD\n4\n1 0 0 0\n$ENDNOD\n";
  run("gmsh format version 1", mesh_file("version1.msh"));
  write_msh("truncated.msh", "2.2 0 8", tet, 90);
  run("truncated gmsh file", mesh_file("truncated.msh"));
  write_msh("nan.msh", "2.2 0 8", "4\n1 0 0 0\n2 nan 0 0\n3 0 1 0\n4 0 0 1\n");
  run("NaN coordinate", mesh_file("nan.msh"));
  write_msh("huge.msh",
            "2.2 0 8",
            "4\n1 0 0 0\n2 1e300 0 0\n3 0 1 0\n4 0 0 1\n");
  run("coordinate near 1e300", mesh_file("huge.msh"));
  write_msh("corrupt_count.msh", "2.2 0 8", "4000000000000000000\n" + tet);
  run("corrupt node count", mesh_file("corrupt_count.msh"));
  std::ofstream("mesh.stl") << "solid x\nendsolid x\n";
  run("unknown mesh suffix", mesh_file("mesh.stl"));
  std::ofstream("mesh.inp") << "*NODE\n1, 0, 0, 0\n";
  run("Abaqus file", mesh_file("mesh.inp"));
  std::ofstream("mesh.vtu") << "<VTKFile/>\n";
  run("VTU file", mesh_file("mesh.vtu"));
  std::filesystem::create_directories("a_folder.msh");
  run("folder as mesh file", mesh_file("a_folder.msh"));
  run("scale to 1e300", "subsection Mesh\n set Scale = 1e300\nend\n");
  run("upper corner below lower corner",
      "subsection Mesh\n set Box lower corner = 0, 0, 2\nend\n");

  // --- values out of range
  const std::string plane =
    "subsection Contact\n set Contact surfaces = 4\n"
    " set Number of obstacles = 1\n subsection Obstacle 0\n";
  run("zero obstacle penalty", plane + "  set Penalty factor = 0\n end\nend\n");
  run("sphere of radius zero",
      plane + "  set Type = sphere\n  set Radius = 0\n end\nend\n");
  run("augmented Lagrangian without an obstacle",
      "subsection Contact\n set Augmented Lagrangian = true\nend\n");
  run("augmented Lagrangian with a zero penalty",
      plane + "  set Penalty factor = 0\n end\n"
              " set Augmented Lagrangian = true\nend\n");
  run("zero pair penalty",
      "subsection Contact\n set Contact surfaces = 4\n"
      " set Number of pairs = 1\n subsection Pair 0\n"
      "  set Penalty factor = 0\n end\nend\n");
  run("shear modulus 1e300",
      "subsection Bodies\n subsection Body 0\n  set Mu = 1e300\n end\nend\n");
  run("Veronda exponent 1e4",
      "subsection Bodies\n subsection Body 0\n  set Model = Veronda\n"
      "  set Beta = 1e4\n end\nend\n");
  run("residual tolerance that accepts the unloaded state",
      "subsection Newton\n set Residual tolerance = 10\nend\n");
  run("every n steps 0", "subsection Output\n set Every n steps = 0\nend\n");
  run("base name with a folder",
      "subsection Output\n set Base name = sub/run\nend\n");
  run("no bodies", "subsection Bodies\n set Number of bodies = 0\nend\n");
  run("unknown subsection", "subsection Solver\n set Type = direct\nend\n");
  const std::string falling =
    "subsection Boundary conditions\n set Number of Dirichlet conditions = "
    "0\nend\nsubsection Loads\n set Gravity = 0, 0, -10\nend\n"
    "subsection Time integration\n set Analysis = dynamic\n"
    " set Time step = 0.01\n set End time = 0.05\n";
  run_dynamic("massless body in an explicit run",
              falling + " set Scheme = central difference\nend\n"
                        "subsection Bodies\n subsection Body 0\n"
                        "  set Density = 0\n end\nend\n");
  run_dynamic("time step failing below its minimum",
              "subsection Loads\n set Gravity = 0, 0, -1e7\nend\n"
              "subsection Time integration\n set Analysis = dynamic\n"
              " set Time step = 0.01\n set End time = 0.05\n"
              " set Scheme = Newmark\n set Minimum time step = 0.005\nend\n"
              "subsection Bodies\n subsection Body 0\n"
              "  set Mu = 1\n  set Lambda = 1\n end\nend\n");

  // --- contact on a body without material depth: one box cell of
  // tetrahedra has no interior vertex
  run("pair on a body without depth",
      "subsection Contact\n set Contact surfaces = 0, 1, 2, 3, 4, 5\n"
      " set Number of pairs = 1\nend\n"
      "subsection Mesh\n set Box subdivisions = 1, 1, 1\nend\n");

  // --- KINSOL stopping on its step tolerance far from the solution
  run("KINSOL stopping short",
      "subsection Newton\n set Nonlinear solver = KINSOL\n"
      " subsection KINSOL\n  set Scaled step stopping tolerance = 10\n"
      " end\nend\nsubsection Boundary conditions\n"
      " set Number of tractions = 1\n subsection Traction 0\n"
      "  set Boundary id = 1\n  set Traction = 0, 0, -0.1\n end\nend\n"
      "subsection Load stepping\n set Minimum increment = 0.2\nend\n");

  // --- parameter files, output folders, checkpoints
  const auto load = [](const std::string &name, const std::string &file) {
    try
      {
        Scene::SceneParameters::from_file(file);
        deallog << name << ": no error" << std::endl;
      }
    catch (const std::exception &e)
      {
        deallog << name << ": error: " << error_message(e) << std::endl;
      }
  };
  load("parameter file that is a folder", "a_folder.msh");
  load("missing parameter file", "no_such.prm");
  try
    {
      std::ostringstream out;
      Scene::SceneParameters::print_reference(out, "xml");
    }
  catch (const std::exception &e)
    {
      deallog << "unknown reference format: error: " << error_message(e)
              << std::endl;
    }
  std::ofstream("a_file") << "x";
  run("output folder that is a file",
      "subsection Output\n set Directory = a_file\nend\n");
  run("refusing an older run's files",
      "subsection Output\n set Old results = refuse\nend\n");
  const auto restart = [](const std::string &name, const std::string &file) {
    try
      {
        Checkpoint::read(file);
        deallog << name << ": no error" << std::endl;
      }
    catch (const std::exception &e)
      {
        deallog << name << ": error: " << error_message(e) << std::endl;
      }
  };
  restart("restart without a checkpoint", "no_such/solution-checkpoint.bin");
  std::ofstream("not_a_checkpoint.bin") << "hello";
  restart("restart from a file that is no checkpoint", "not_a_checkpoint.bin");
  {
    Checkpoint c;
    c.kind              = "static";
    c.vectors["u"]      = Vector<double>(100);
    c.scalars["lambda"] = 0.5;
    c.write("whole.bin");
    std::ifstream      in("whole.bin", std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    std::ofstream("cut.bin", std::ios::binary)
      << bytes.str().substr(0, bytes.str().size() - 100);
    restart("truncated checkpoint", "cut.bin");
    const Checkpoint whole = Checkpoint::read("whole.bin");
    try
      {
        whole.vector("u", 99);
      }
    catch (const std::exception &e)
      {
        deallog << "checkpoint of another mesh: error: " << error_message(e)
                << std::endl;
      }
  }
}
