// The knee's geometry (meshes/knee.geo, issue 10): meshed by gmsh at its
// coarsest setting and read as a scene of seven bodies with the sliding
// contact pairs of the flexion scene. Checks what the geometry promises:
// every body is present; the attached interfaces share nodes (tendon-muscle,
// tendon-patella, ligament-patella, ligament-tibia, skin-fat-tibia) and the
// sliding ones share none (skin-fat on femur, patella, ligament, tendon and
// muscle; patella on femur); every sliding surface has contact triangles and
// every volume body of a pair a finite material depth.

#include "../tests.h"

#include <tissue_contact/simulation/problem.h>

#include <cstdlib>
#include <filesystem>
#include <set>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const std::string geo = std::string(SOURCE_DIR) + "/../../meshes/knee.geo";
  const std::string cmd = "gmsh -3 -setnumber h 0.04 -setnumber n_2pi 5 " +
                          geo + " -o knee.msh > gmsh.log 2>&1";
  AssertThrow(std::system(cmd.c_str()) == 0, ExcMessage("gmsh failed: " + cmd));

  static const char *names[] = {
    "femur", "tibia", "patella", "ligament", "tendon", "muscle", "skin-fat"};
  std::string prm = "subsection Mesh\n set Source = file\n set File = "
                    "knee.msh\nend\nsubsection Bodies\n"
                    " set Number of bodies = 7\n";
  for (unsigned int b = 0; b < 7; ++b)
    prm += " subsection Body " + std::to_string(b) +
           "\n  set Name = " + names[b] +
           "\n  set Material id = " + std::to_string(b + 1) +
           "\n  set Model = neo-Hookean\n  set Mu = 1\n  set Lambda = 10\n"
           " end\n";
  prm +=
    "end\nsubsection Boundary conditions\n subsection Dirichlet 0\n"
    "  set Boundary id = 21\n end\nend\n"
    "subsection Contact\n set Contact surfaces = 11, 13, 14, 15, 16, 17, 18\n"
    " set Number of pairs = 5\n"
    " subsection Pair 0\n  set Surface body = 7\n  set Volume body = 7\n end\n"
    " subsection Pair 1\n  set Surface body = 7\n  set Volume body = 1\n end\n"
    " subsection Pair 2\n  set Surface body = 1\n  set Volume body = 7\n end\n"
    " subsection Pair 3\n  set Surface body = 3\n  set Volume body = 1\n end\n"
    " subsection Pair 4\n  set Surface body = 1\n  set Volume body = 3\n end\n"
    "end\n";
  const Problem problem(Scene::SceneParameters::from_string(prm));
  const auto   &tria = problem.get_scene().triangulation;

  std::array<std::set<unsigned int>, 8> vertices;
  std::array<unsigned int, 8>           n_cells{};
  for (const auto &cell : tria.active_cell_iterators())
    {
      ++n_cells[cell->material_id()];
      for (const unsigned int v : cell->vertex_indices())
        vertices[cell->material_id()].insert(cell->vertex_index(v));
    }
  unsigned int present = 0;
  for (unsigned int b = 1; b <= 7; ++b)
    present += n_cells[b] > 0;
  deallog << "bodies with cells: " << present << " of 7" << std::endl;

  const auto shared = [&](const unsigned int a, const unsigned int b) {
    unsigned int n = 0;
    for (const unsigned int v : vertices[a])
      n += vertices[b].count(v);
    return n;
  };
  const std::vector<std::pair<unsigned int, unsigned int>> attached = {
    {5, 6}, {5, 3}, {4, 3}, {4, 2}, {7, 2}};
  const std::vector<std::pair<unsigned int, unsigned int>> sliding = {
    {7, 1}, {7, 3}, {7, 4}, {7, 5}, {7, 6}, {3, 1}, {1, 2}};
  deallog << "attached interfaces sharing nodes:";
  for (const auto &[a, b] : attached)
    deallog << " " << names[a - 1] << "-" << names[b - 1] << " "
            << (shared(a, b) > 0 ? "yes" : "NO");
  deallog << std::endl << "sliding interfaces sharing no node:";
  for (const auto &[a, b] : sliding)
    deallog << " " << names[a - 1] << "-" << names[b - 1] << " "
            << (shared(a, b) == 0 ? "yes" : "NO");
  deallog << std::endl;

  std::map<types::boundary_id, unsigned int> faces;
  for (const auto &cell : tria.active_cell_iterators())
    for (const auto &face : cell->face_iterators())
      if (face->at_boundary())
        ++faces[face->boundary_id()];
  deallog << "boundary ids with faces:";
  for (const auto &[id, n] : faces)
    deallog << " " << id;
  deallog << std::endl;

  const auto  &g         = problem.contact_assembler()->vertex_depth();
  unsigned int n_missing = 0;
  for (const unsigned int b : {1u, 3u, 7u})
    for (const unsigned int v : vertices[b])
      n_missing += !std::isfinite(g[v]);
  deallog << "vertices of the volume bodies (femur, patella, skin-fat) "
             "without a material depth: "
          << n_missing << std::endl;
}
