// Stiffness-proportional damping beta K and large rotations: a cantilever
// 1 x 0.12 x 0.12 (P1, mu = 1000, lambda = 2000, density 1) released under
// gravity 10 with beta = 0.04 (Newmark, dt = 0.01). Its tip rotates by
// about 0.2 rad. Printed per model and K: the largest kinetic energy of
// the second swing (t in [0.3, 0.6]) over that of the first (t < 0.3).
// Linear elasticity swings back as its modal damping says. Neo-Hookean with
// K_0 (the reference tangent: the linear viscous stress of the reference
// configuration, not objective) stops after the first swing and creeps;
// with the tangent at the start of each step it swings back
// (doc/theory/06-dynamics.md, sec. 1).

#include "../tests.h"
#include "scenes.h"

#include <tissue_contact/dynamics/mass_matrix.h>
#include <tissue_contact/dynamics/time_integrator.h>
#include <tissue_contact/simulation/problem.h>

#include <sstream>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

namespace
{
  /** The oscillator's bar (scenes.h), slenderer, stiffer, under gravity. */
  std::string
  cantilever(const std::string &model)
  {
    return std::string(DynamicsTestScenes::bar) + R"(
subsection Mesh
  set Box upper corner = 1, 0.12, 0.12
  set Box subdivisions = 10, 1, 1
end
subsection Bodies
  subsection Body 0
    set Model  = )" +
           model +
           R"(
    set Mu     = 1000
    set Lambda = 2000
  end
end
subsection Loads
  set Gravity = 0, 0, -10
end
)";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const std::tuple<const char *, const char *, bool> cases[] = {
    {"linear", "K_0", false},
    {"neo-Hookean", "K_0", false},
    {"neo-Hookean", "K(u_n)", true}};
  for (const auto &[model, tangent, current] : cases)
    {
      Problem sim(Scene::SceneParameters::from_string(cantilever(model)));
      SparseMatrix<double> M(sim.discretization().sparsity_pattern);
      Dynamics::assemble_consistent_mass(sim.discretization(),
                                         sim.get_scene().body_data(),
                                         M);
      Dynamics::TimeIntegrator::Parameters p;
      p.rayleigh_beta         = 0.04;
      p.rayleigh_beta_current = current;
      Dynamics::TimeIntegrator integrator(p, sim, &M, nullptr);
      Dynamics::State          s;
      s.u.reinit(sim.n_dofs());
      s.v.reinit(sim.n_dofs());
      integrator.initialize(s);
      double first = 0., second = 0., next = 0.01;
      while (s.t < 0.6 - 1e-9)
        {
          integrator.step(s, 0.01, next);
          double &swing = s.t < 0.3 + 1e-9 ? first : second;
          swing         = std::max(swing, integrator.kinetic_energy(s));
        }
      deallog << model << ", beta " << tangent
              << ": second swing's kinetic energy / first's "
              << std::setprecision(2) << second / first << std::setprecision(6)
              << std::endl;
    }
}
