// Locking, and the volume term at the vertices that removes most of it
// (doc/theory/08-nodal-pressure.md): a short cantilever, the cube [0, 1]^3
// clamped on x = 0 and bent by its own weight (density 1, gravity 100),
// uncoupled neo-Hookean with mu = 1000 and Poisson's ratio 0.4999
// (kappa = 4 999 666.7), on the unstructured P1 mesh of
// meshes/block_cantilever.geo at h = 0.125 (2 148 unknowns). Printed for the
// displacement-only element (Volumetric term = pointwise) and the vertex
// volume term (nodal average): the strain energy, its relative error
// against a locking-free reference, increments and Newton iterations.
//
// The reference, 2.64 (strain energy), is FEniCSx's three-field
// Taylor-Hood solution of the same energy (P2 displacement, P1 dilatation
// and pressure) on n^3 cube meshes, n = 4, 8, 12 (2.560, 2.607, 2.620),
// extrapolated to h = 0 with the observed order 1.2:
// tests/performance/peer_incompressible.py prints it.
//
// Measured (prm/studies/locking_free.prm, doc/users/choosing.md): on three
// meshes of this geometry the displacement-only element's error stays at
// 0.46-0.50, the vertex volume term's falls from 0.20 to 0.15 and 0.076.

#include "../tests.h"

#include <tissue_contact/simulation/static_simulation.h>

#include <sstream>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

namespace
{
  constexpr double reference = 2.64;

  std::string
  scene(const std::string &volumetric_term)
  {
    return "subsection Mesh\n"
           "  set Source  = geo\n"
           "  set File    = " +
           std::string(SOURCE_DIR) +
           "/../../meshes/block_cantilever.geo\n"
           "  set Gmsh options = -setnumber h 0.125\n"
           "end\n"
           "subsection Bodies\n"
           "  subsection Body 0\n"
           "    set Material id     = 1\n"
           "    set Model           = neo-Hookean\n"
           "    set Formulation     = uncoupled\n"
           "    set Mu              = 1000\n"
           "    set Bulk modulus    = 4999666.7\n"
           "    set Volumetric term = " +
           volumetric_term +
           "\n"
           "    set Density         = 1\n"
           "  end\n"
           "end\n"
           "subsection Boundary conditions\n"
           "  subsection Dirichlet 0\n"
           "    set Boundary id = 1\n"
           "  end\n"
           "end\n"
           "subsection Loads\n"
           "  set Gravity = 0, 0, -100\n"
           "end\n"
           "subsection Linear solver\n"
           "  set Type = direct\n"
           "end\n"
           "subsection Output\n"
           "  set Write VTU    = false\n"
           "  set Print timing = false\n"
           "  set Directory    = .\n"
           "end\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  deallog << "locking-free reference strain energy " << reference << std::endl;
  for (const std::string term : {"pointwise", "nodal average"})
    {
      std::ostringstream log;
      StaticSimulation   sim(Scene::SceneParameters::from_string(scene(term)),
                           log);
      sim.solve_quietly();
      const double W     = sim.problem().strain_energy(sim.solution());
      const double error = std::abs(W - reference) / reference;
      // (the iteration counts are left out: at this Poisson's ratio the
      // displacement-only element's Newton path moves with rounding)
      deallog << "Volumetric term = " << term << ": " << sim.problem().n_dofs()
              << " unknowns, strain energy " << std::setprecision(3) << W
              << ", relative error " << std::setprecision(2) << error
              << (error > 0.3 ? " (> 30 %)" : "") << std::setprecision(6)
              << std::endl;
    }
}
