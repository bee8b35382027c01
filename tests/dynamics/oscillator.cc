// A single-mode oscillator built from the FE model (the textbook's
// time-step study): a clamped linear elastic bar [0,1] x [0,0.2]^2 (P1,
// density 1, mu = lambda = 1) released from rest in its lowest mode phi
// (inverse iteration on K phi = omega^2 M phi), small amplitude.
//  - Newmark (average acceleration) over dt = T/10, T/20, T/40: the period
//    measured from the modal coordinate's zero crossings against
//    T = 2 pi / omega (period elongation ~ (omega dt)^2 / 12: second order)
//    and the energy after 5 periods (conserved);
//  - implicit Euler at the same steps: the energy dissipated;
//  - central difference (lumped mass) at dt = f * 2 / omega_max (omega_max
//    by power iteration on M_L^-1 K) for f = 0.5, 0.9, 1.1, 1.5: stable
//    below the estimate, blow-up detected and reported above it;
//  - quasistatic (no inertia, viscosity alpha M): the mode relaxes as
//    alpha M u' + K u = 0 says, u = exp(-t / tau) phi with tau =
//    alpha / omega^2; backward Euler's factor per step is
//    1 / (1 + dt / tau);
//  - the dissertation's nodal viscosity D (a diagonal) as the damping of
//    Newmark: the energy after 5 periods against exp(-2 zeta omega t) with
//    the modal damping ratio zeta = phi^T D phi / (2 omega phi^T M phi)
//    (light damping; D couples the modes a little).

#include "../tests.h"
#include "scenes.h"

#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/dynamics/mass_matrix.h>
#include <tissue_contact/dynamics/time_integrator.h>
#include <tissue_contact/simulation/static_simulation.h>

#include <deal.II/lac/sparse_direct.h>
#include <deal.II/numerics/matrix_tools.h>

#include <sstream>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  DynamicsTestScenes::BarOscillator bar;
  auto                             &sim       = bar.sim;
  const auto                        n         = bar.n;
  const auto                       &M         = bar.M;
  const auto                       &M_lumped  = bar.M_lumped;
  const auto                       &phi       = bar.phi;
  const double                      omega     = bar.omega;
  const double                      T         = bar.T;
  const double                      dt_stable = 2. / bar.omega_max;
  deallog << "lowest mode: omega " << std::setprecision(5) << omega
          << ", period T " << T << std::setprecision(6) << std::endl;
  const auto   modal = [&](const Vector<double> &u) { return bar.modal(u); };
  const double amplitude = 1e-3;

  const auto run = [&](const Dynamics::Scheme scheme,
                       const double           dt,
                       const double           duration,
                       double                &period,
                       double                &energy_ratio,
                       std::string           &failure) {
    Dynamics::TimeIntegrator::Parameters p;
    p.scheme = scheme;
    Dynamics::TimeIntegrator integrator(
      p,
      sim,
      scheme == Dynamics::Scheme::central_difference ? nullptr : &M,
      &M_lumped);
    Dynamics::State s;
    s.u = phi;
    s.u *= amplitude;
    s.v.reinit(n);
    integrator.initialize(s);
    const auto energy = [&](const Dynamics::State &st) {
      return integrator.kinetic_energy(st) + sim.energy(st.u, 1.);
    };
    const double        E0 = energy(s);
    std::vector<double> crossings;
    double              q_previous = modal(s.u), next = dt;
    failure.clear();
    try
      {
        while (s.t < duration - 1e-12 * dt)
          {
            const double t_previous = s.t;
            integrator.step(s, dt, next);
            const double q = modal(s.u);
            if (q_previous < 0. && q >= 0.)
              crossings.push_back(t_previous + (s.t - t_previous) * q_previous /
                                                 (q_previous - q));
            q_previous = q;
          }
      }
    catch (const std::exception &e)
      {
        failure = TissueContact::error_message(e);
      }
    period       = crossings.size() >= 2 ?
                     (crossings.back() - crossings.front()) / (crossings.size() - 1) :
                     0.;
    energy_ratio = energy(s) / E0;
  };

  deallog << "Newmark (average acceleration) and implicit Euler, 5 periods:"
          << std::endl;
  for (const unsigned int steps : {10u, 20u, 40u})
    {
      const double dt = T / steps;
      double       period_n, ratio_n, period_e, ratio_e;
      std::string  failure;
      run(Dynamics::Scheme::newmark, dt, 5. * T, period_n, ratio_n, failure);
      run(Dynamics::Scheme::implicit_euler,
          dt,
          5. * T,
          period_e,
          ratio_e,
          failure);
      const double elongation = std::pow(omega * dt, 2) / 12.;
      deallog << "  dt = T/" << steps
              << ": Newmark period / T - 1 = " << std::setprecision(3)
              << period_n / T - 1.
              << " (theory (omega dt)^2/12 = " << elongation
              << "), energy change " << error_bound(std::abs(ratio_n - 1.), -10)
              << "; implicit Euler energy after 5 periods / initial " << ratio_e
              << std::setprecision(6) << std::endl;
    }

  deallog << "element-size estimate h/c / (2/omega_max) = "
          << std::setprecision(3)
          << Dynamics::stable_time_step_estimate(sim.discretization(),
                                                 sim.get_scene().body_data()) /
               dt_stable
          << std::setprecision(6) << std::endl;
  deallog << "central difference, lumped mass, 2 periods; stable estimate "
             "2/omega_max = "
          << std::setprecision(4) << dt_stable
          << " (T / dt_stable = " << std::setprecision(4) << T / dt_stable
          << ")" << std::setprecision(6) << std::endl;
  for (const double f : {0.5, 0.9, 1.1, 1.5})
    {
      double      period, ratio;
      std::string failure;
      run(Dynamics::Scheme::central_difference,
          f * dt_stable,
          2. * T,
          period,
          ratio,
          failure);
      deallog << "  dt = " << std::setprecision(2) << f << std::setprecision(6)
              << " * estimate: ";
      if (failure.empty())
        deallog << "stable, period / T - 1 = " << std::setprecision(2)
                << period / T - 1. << ", energy / initial "
                << std::setprecision(3) << ratio << std::setprecision(6)
                << std::endl;
      else
        deallog << "unstable, detected: "
                << failure.substr(0, failure.find(" at t =")) << std::endl;
    }

  {
    Dynamics::TimeIntegrator::Parameters p;
    p.scheme         = Dynamics::Scheme::quasistatic;
    p.rayleigh_alpha = 1.;
    Dynamics::TimeIntegrator integrator(p, sim, &M, &M_lumped);
    Dynamics::State          s;
    s.u = phi;
    s.u *= amplitude;
    s.v.reinit(n);
    integrator.initialize(s);
    const double tau = p.rayleigh_alpha / (omega * omega), dt = 0.1 * tau;
    double       next = dt;
    for (unsigned int k = 0; k < 20; ++k)
      integrator.step(s, dt, next);
    const double ratio = modal(s.u) / amplitude;
    deallog << "quasistatic, viscosity alpha M (alpha = 1), 20 steps of tau/10 "
               "(tau = alpha/omega^2): amplitude / (1 + dt/tau)^-20 - 1 "
            << error_bound(std::abs(ratio * std::pow(1.1, 20) - 1.), -10)
            << "; amplitude " << std::setprecision(4) << ratio
            << " (exp(-2) = " << std::exp(-2.) << ")" << std::setprecision(6)
            << std::endl;
  }

  {
    // tau of D_a = tau sum_e mu_e h_e / n_e such that zeta = 0.01
    const Vector<double> D1         = sim.quasi_viscosity_diagonal(1.);
    double               phi_D1_phi = 0.;
    for (types::global_dof_index i = 0; i < n; ++i)
      phi_D1_phi += D1[i] * phi[i] * phi[i];
    const double                         zeta = 0.01;
    Dynamics::TimeIntegrator::Parameters p;
    p.nodal_viscosity = 2. * zeta * omega * bar.phi_M_phi / phi_D1_phi;
    Dynamics::TimeIntegrator integrator(p, sim, &M, &M_lumped);
    Dynamics::State          s;
    s.u = phi;
    s.u *= amplitude;
    s.v.reinit(n);
    integrator.initialize(s);
    const auto energy = [&](const Dynamics::State &st) {
      return integrator.kinetic_energy(st) + sim.energy(st.u, 1.);
    };
    const double E0 = energy(s), dt = T / 40.;
    double       next = dt;
    while (s.t < 5. * T - 1e-9)
      integrator.step(s, dt, next);
    deallog << "Newmark with the nodal viscosity (zeta = 0.01 in the lowest "
               "mode), T/40, 5 periods: energy / initial "
            << std::setprecision(4) << energy(s) / E0
            << " (exp(-2 zeta omega t) = " << std::exp(-2. * zeta * omega * s.t)
            << ")" << std::setprecision(6) << std::endl;
  }
}
