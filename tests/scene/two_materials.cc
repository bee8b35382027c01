// A body of two materials (meshes/two_materials.geo: material 1 on
// x in [0, 1], material 2 on [1, 2], conforming at x = 1):
//  - in series under a uniaxial traction sigma on x = 2 (rollers on x = 0,
//    y = 0, z = 0; linear elasticity, Young's moduli E1 and E2, nu = 0): the
//    stiffness of each part, sigma over its strain, and of the whole bar,
//    against E1, E2 and the series value 2 / (1/E1 + 1/E2);
//  - one body for contact ("Contact body"): with contact surface x = 0
//    only, material 2 has no contact face of its own; as part of body 1
//    its material depth is the distance to x = 0 across the interface,
//    g = x at every vertex; without the grouping its vertices get none.

#include "../tests.h"

#include <tissue_contact/simulation/static_simulation.h>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

namespace
{
  std::string
  bar(const std::string &extra)
  {
    // nu = 0 (lambda = 0), E = 2 mu: the parts contract nothing sideways,
    // so the interface keeps the stress uniaxial (with nu > 0 the two
    // parts' lateral strains -nu sigma / E would differ)
    return "subsection Mesh\n set Source = file\n set File = " +
           std::string(SOURCE_DIR) +
           "/two_materials.msh\nend\n"
           "subsection Bodies\n set Number of bodies = 2\n"
           " subsection Body 0\n  set Name = soft\n  set Material id = 1\n"
           "  set Model = linear\n  set Mu = 1.25\n  set Lambda = 0\n end\n"
           " subsection Body 1\n  set Name = stiff\n  set Material id = 2\n"
           "  set Model = linear\n  set Mu = 5\n  set Lambda = 0\n" +
           extra +
           " end\nend\n"
           "subsection Output\n set Write VTU = false\n"
           " set Print timing = false\n set Directory = .\nend\n";
  }

  void
  series_stiffness()
  {
    const double      E1 = 2.5, E2 = 10., sigma = 0.01;
    const std::string bc =
      "subsection Boundary conditions\n"
      " set Number of Dirichlet conditions = 3\n set Number of tractions = 1\n"
      " subsection Dirichlet 0\n  set Boundary id = 1\n  set Components = x\n"
      " end\n"
      " subsection Dirichlet 1\n  set Boundary id = 3\n  set Components = y\n"
      " end\n"
      " subsection Dirichlet 2\n  set Boundary id = 4\n  set Components = z\n"
      " end\n"
      " subsection Traction 0\n  set Boundary id = 2\n"
      "  set Traction = 0.01, 0, 0\n end\nend\n";
    std::ostringstream log;
    StaticSimulation   sim(Scene::SceneParameters::from_string(bar("") + bc),
                         log);
    sim.solve_quietly();
    const auto &disc = sim.problem().discretization();
    const auto  X    = disc.support_points();
    const auto  comp = disc.dof_components();
    // mean u_x on the planes x = 0, 1, 2
    std::array<double, 3>       sum{};
    std::array<unsigned int, 3> count{};
    for (unsigned int i = 0; i < X.size(); ++i)
      for (unsigned int k = 0; k < 3; ++k)
        if (comp[i] == 0 && std::abs(X[i][0] - k) < 1e-12)
          {
            sum[k] += sim.solution()[i];
            ++count[k];
          }
    const double u0 = sum[0] / count[0], u1 = sum[1] / count[1],
                 u2 = sum[2] / count[2];
    const double k1 = sigma / (u1 - u0), k2 = sigma / (u2 - u1),
                 k = 2. * sigma / (u2 - u0), series = 2. / (1. / E1 + 1. / E2);
    deallog << "series bar under uniaxial stress: stiffness of part 1 " << k1
            << " (E1 " << E1 << ": " << error_bound(std::abs(k1 - E1) / E1)
            << "), part 2 " << k2 << " (E2 " << E2 << ": "
            << error_bound(std::abs(k2 - E2) / E2) << "), whole bar " << k
            << " (series " << series << ": "
            << error_bound(std::abs(k - series) / series) << ")" << std::endl;
  }

  void
  one_body_of_two_materials()
  {
    const std::string contact =
      "subsection Contact\n set Contact surfaces = 1\n set Number of pairs = 1\n"
      " subsection Pair 0\n  set Surface body = 1\n  set Volume body = 1\n"
      " end\nend\n"
      "subsection Boundary conditions\n subsection Dirichlet 0\n"
      "  set Boundary id = 1\n end\nend\n";
    for (const bool grouped : {true, false})
      {
        const Problem problem(Scene::SceneParameters::from_string(
          bar(grouped ? "  set Contact body = 1\n" : "") + contact));
        const auto   &g   = problem.contact_assembler()->vertex_depth();
        const auto   &X   = problem.get_scene().triangulation.get_vertices();
        double        err = 0.;
        unsigned int  n_without = 0;
        for (unsigned int v = 0; v < X.size(); ++v)
          if (std::isfinite(g[v]))
            err = std::max(err, std::abs(g[v] - X[v][0]));
          else
            ++n_without;
        deallog << (grouped ? "materials 1 and 2 one body: " :
                              "materials 1 and 2 separate: ")
                << X.size() - n_without
                << " vertices with a depth, max |g - x| "
                << error_bound(err, -14) << "; " << n_without
                << " vertices without one" << std::endl;
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  series_stiffness();
  one_body_of_two_materials();
}
