// A block dropped on a rigid plane (Newmark, average acceleration): a
// neo-Hookean cube of side 0.2 and density 1, its bottom 0.1 above the
// plane z = 0, under gravity g = 10, with mass-proportional Rayleigh
// damping alpha = 5 (a drag); contact by the area-integrated penalty on
// the bottom face (eps = 1e3). Printed:
//  - the first contact time against the analytic fall with drag;
//  - the momentum balance: p(t) - p(0) against the impulse of the contact
//    force, the weight and the drag (trapezoid rule, as Newmark's
//    gamma = 1/2 implies);
//  - the energy balance: kinetic + elastic + contact + gravity potential +
//    dissipated (integral of alpha v^T M v) against the initial energy;
//  - the state at t = 3: at rest, the contact force equal to the weight;
//  - the same block quasistatic (no inertia, the drag as a viscosity): it
//    sinks at g / alpha, touches at t = h alpha / g, and rests on the plane.

#include "../tests.h"
#include "scenes.h"

#include <tissue_contact/dynamics/mass_matrix.h>
#include <tissue_contact/dynamics/time_integrator.h>
#include <tissue_contact/simulation/static_simulation.h>

#include <sstream>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  DynamicsTestScenes::FallingBlock block;
  auto                            &sim = block.sim;
  const auto                       n   = block.n;
  const auto                      &M   = block.M;
  const auto                      &ez  = block.ez;

  const double g = 10., alpha = 5., mass = block.mass, h = 0.1;
  Dynamics::TimeIntegrator::Parameters p;
  p.scheme         = Dynamics::Scheme::newmark;
  p.rayleigh_alpha = alpha;
  Dynamics::TimeIntegrator integrator(p, sim, &M, nullptr);

  Dynamics::State s;
  s.u.reinit(n);
  s.v.reinit(n);
  integrator.initialize(s);

  Vector<double> Mv(n);
  const auto     momentum = [&](const Dynamics::State &st) {
    M.vmult(Mv, st.v);
    return ez * Mv;
  };
  const auto contact_force = [&](const Dynamics::State &st) {
    return sim.contact_assembler()->obstacle_force(st.u)[2];
  };
  // total energy: kinetic + elastic - work of gravity + contact
  const auto energy = [&](const Dynamics::State &st) {
    return integrator.kinetic_energy(st) + sim.energy(st.u, 1.);
  };
  const auto dissipation_rate = [&](const Dynamics::State &st) {
    M.vmult(Mv, st.v);
    return alpha * (st.v * Mv);
  };
  const auto net_force = [&](const Dynamics::State &st) {
    return contact_force(st) - mass * g - alpha * momentum(st);
  };

  const double E0 = energy(s), p0 = momentum(s);
  double       impulse = 0., dissipated = 0., first_contact = -1.;
  double       momentum_error = 0., energy_error = 0., E_scale = 0.;
  double       dt = 2e-3, next = dt;
  while (s.t < 3. - 1e-9)
    {
      const Dynamics::State before = s;
      const double          taken  = integrator.step(s, dt, next);
      impulse += 0.5 * taken * (net_force(before) + net_force(s));
      dissipated +=
        0.5 * taken * (dissipation_rate(before) + dissipation_rate(s));
      if (first_contact < 0. && contact_force(s) > 0.)
        first_contact = before.t;
      momentum_error =
        std::max(momentum_error, std::abs(momentum(s) - p0 - impulse));
      E_scale = std::max(E_scale, std::abs(energy(s)));
      energy_error =
        std::max(energy_error, std::abs(energy(s) + dissipated - E0));
    }
  // the fall with drag: z(t) = -(g/alpha) t + (g/alpha^2)(1 - exp(-alpha t))
  double lo = 0., hi = 1.;
  for (unsigned int it = 0; it < 60; ++it)
    {
      const double t = 0.5 * (lo + hi);
      const double z =
        -(g / alpha) * t + (g / (alpha * alpha)) * (1. - std::exp(-alpha * t));
      (z > -h ? lo : hi) = t;
    }
  deallog << "first contact at t = " << std::setprecision(3) << first_contact
          << " (analytic fall with drag " << lo << ", step 0.002)" << std::endl;
  deallog << "momentum balance: max |p(t) - p(0) - impulse| / (m g t_end) "
          << error_bound(momentum_error / (mass * g * 3.), -10) << std::endl;
  deallog << "energy balance: max |E(t) + dissipated - E(0)| / max |E| "
          << std::setprecision(2) << energy_error / E_scale << ", dissipated "
          << dissipated / (E0 - energy(s)) << " of E(0) - E(3)" << std::endl;
  deallog << "at t = 3: kinetic energy / m g h "
          << error_bound(integrator.kinetic_energy(s) / (mass * g * h), -4)
          << ", contact force / weight " << std::setprecision(4)
          << contact_force(s) / (mass * g) << std::setprecision(6) << std::endl;

  {
    Dynamics::TimeIntegrator::Parameters q;
    q.scheme         = Dynamics::Scheme::quasistatic;
    q.rayleigh_alpha = alpha;
    Dynamics::TimeIntegrator creeping(q, sim, &M, nullptr);
    Dynamics::State          c;
    c.u.reinit(n);
    c.v.reinit(n);
    creeping.initialize(c);
    double touch = -1., next = 0.005, speed = 0.;
    while (c.t < 1. - 1e-9)
      {
        const Dynamics::State before = c;
        creeping.step(c, 0.005, next);
        if (c.t < 0.03 + 1e-9)
          speed = -momentum(c) / mass;
        if (touch < 0. && contact_force(c) > 0.)
          touch = before.t;
      }
    deallog << "quasistatic: sinks at " << std::setprecision(4) << speed
            << " (g/alpha " << g / alpha << "), touches at t = " << touch
            << " (h alpha/g " << h * alpha / g
            << ", step 0.005), at t = 1 contact force / weight "
            << contact_force(c) / (mass * g) << std::setprecision(6)
            << std::endl;
  }
}
