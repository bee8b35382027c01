// Prescribed motions in every time integrator: the clamped bar of the
// oscillator test (linear elastic, [0,1] x [0,0.2]^2, its lowest period
// T = 16.46) has its clamped face lifted by d = (0, 0, 0.01), ramped in
// over T (Ramp time), with a drag alpha = 0.2 (modal damping ratio 0.26).
// The bar follows as a rigid body and, once the oscillation it started
// has died out, every node is displaced by d: printed per scheme, the
// largest |u - d| / |d| over the nodes at t = 8 T, and the largest one
// after the ramp (how far inertia or viscosity made the bar lag and
// swing). Newmark keeps a little of the high-frequency motion the ramp's
// kink started: it has no numerical damping and the drag damps high modes
// weakly (damping ratio alpha / (2 omega)).

#include "../tests.h"
#include "scenes.h"

#include <tissue_contact/dynamics/mass_matrix.h>
#include <tissue_contact/dynamics/time_integrator.h>
#include <tissue_contact/simulation/problem.h>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  std::string       scene = DynamicsTestScenes::bar;
  const std::string clamp = "set Boundary id = 0";
  scene.replace(scene.find(clamp),
                clamp.size(),
                clamp + "\n    set Translation = 0, 0, 0.01");
  std::ostringstream   log;
  Problem              sim(Scene::SceneParameters::from_string(scene));
  const auto          &disc      = sim.discretization();
  const auto           n         = disc.n_dofs();
  const auto           component = disc.dof_components();
  const auto           bodies    = sim.get_scene().body_data();
  SparseMatrix<double> M(disc.sparsity_pattern);
  Dynamics::assemble_consistent_mass(disc, bodies, M);
  const Vector<double> M_lumped = Dynamics::lumped_mass(disc, bodies);
  const double         T        = 16.458;
  const double dt_stable = Dynamics::stable_time_step_estimate(disc, bodies);

  const auto deviation = [&](const Vector<double> &u) {
    double e = 0.;
    for (types::global_dof_index i = 0; i < n; ++i)
      e = std::max(e, std::abs(u[i] - (component[i] == 2 ? 0.01 : 0.)));
    return e / 0.01;
  };
  const std::pair<const char *, Dynamics::Scheme> schemes[] = {
    {"Newmark", Dynamics::Scheme::newmark},
    {"implicit Euler", Dynamics::Scheme::implicit_euler},
    {"central difference", Dynamics::Scheme::central_difference},
    {"quasistatic", Dynamics::Scheme::quasistatic}};
  for (const auto &[name, scheme] : schemes)
    {
      Dynamics::TimeIntegrator::Parameters p;
      p.scheme         = scheme;
      p.rayleigh_alpha = 0.2;
      p.ramp_time      = T;
      const bool explicit_scheme =
        scheme == Dynamics::Scheme::central_difference;
      Dynamics::TimeIntegrator integrator(p,
                                          sim,
                                          explicit_scheme ? nullptr : &M,
                                          &M_lumped);
      Dynamics::State          s;
      s.u.reinit(n);
      s.v.reinit(n);
      integrator.initialize(s);
      const double dt   = explicit_scheme ? 0.5 * dt_stable : T / 20.;
      double       next = dt, largest = 0.;
      while (s.t < 8. * T - 1e-9)
        {
          integrator.step(s, std::min(dt, 8. * T - s.t), next);
          if (s.t > T)
            largest = std::max(largest, deviation(s.u));
        }
      deallog << name << ": max |u - d| / |d| at t = 8T "
              << error_bound(deviation(s.u), -8) << ", largest after the ramp "
              << std::setprecision(2) << largest << std::setprecision(6)
              << std::endl;
    }
}
