// KINSOL (SUNDIALS, through deal.II) as the nonlinear solver of every load
// increment, against the project's Newton loop, on a hyperelastic scene (a
// Mooney-Rivlin block bent by a traction) and on a contact scene
// (prm/stacked_blocks.prm, with quasi-viscosity): the same
// equilibrium (relative difference printed) and the iteration counts.

#include "../tests.h"

#include <tissue_contact/simulation/static_simulation.h>

#include <fstream>
#include <sstream>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

namespace
{
  const std::string output = R"(
subsection Output
  set Write VTU    = false
  set Print timing = false
  set Directory    = .
end
)";

  const std::string hyperelastic = R"(
subsection Mesh
  set Box upper corner = 1, 0.2, 0.2
  set Box subdivisions = 6, 2, 2
end
subsection Bodies
  subsection Body 0
    set Model = Mooney-Rivlin
    set C1    = 1
    set C2    = 0.5
    set a     = 2
  end
end
subsection Boundary conditions
  set Number of tractions = 1
  subsection Dirichlet 0
    set Boundary id = 0
  end
  subsection Traction 0
    set Boundary id = 1
    set Traction    = 0, 0.3, 0.1
  end
end
)";

  /** prm/stacked_blocks.prm */
  std::string
  contact()
  {
    return project_prm("stacked_blocks.prm");
  }


  void
  compare(const std::string &name, const std::string &scene)
  {
    // Newton with the residual line search, Newton with the energy line
    // search, KINSOL (its own line search on |F|^2)
    const char    *settings[3] = {"  set Nonlinear solver = Newton\n"
                                     "  set Line search = residual\n",
                                  "  set Nonlinear solver = Newton\n"
                                     "  set Line search = energy\n",
                                  "  set Nonlinear solver = KINSOL\n"};
    Vector<double> u[3];
    unsigned int   iterations[3];
    for (const unsigned int s : {0u, 1u, 2u})
      {
        std::ostringstream log;
        StaticSimulation   sim(Scene::SceneParameters::from_string(
                               scene + output + "subsection Newton\n" +
                               settings[s] + "end\n"),
                             log);
        iterations[s] = sim.solve_quietly().newton_iterations;
        u[s]          = sim.solution();
      }
    Vector<double> d(u[2]), e(u[1]);
    d -= u[0];
    e -= u[0];
    deallog << name << ": |u_KINSOL - u_Newton| / |u_Newton| "
            << error_bound(d.l2_norm() / u[0].l2_norm(), -8)
            << " (energy line search: "
            << error_bound(e.l2_norm() / u[0].l2_norm(), -8)
            << "); iterations: Newton " << iterations[0]
            << " (residual line search), " << iterations[1]
            << " (energy line search), KINSOL " << iterations[2] << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  compare("Mooney-Rivlin block, traction", hyperelastic);
  compare("stacked blocks, contact", contact());
}
