// IDA (SUNDIALS' variable-order BDF with error control) against the
// exact solution and against Newmark on the single-mode oscillator of
// tests/dynamics/oscillator (a clamped bar released in its lowest mode
// phi; exactly q(t) = A cos(omega t) for the semi-discrete system), and on
// the block dropped on a rigid plane of tests/dynamics/falling_block
// (against Newmark with a small step).

#include "../tests.h"
#include "scenes.h"

#include <tissue_contact/dynamics/ida_integrator.h>
#include <tissue_contact/dynamics/time_integrator.h>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

namespace
{
  void
  oscillator()
  {
    DynamicsTestScenes::BarOscillator bar;
    auto                             &sim   = bar.sim;
    const auto                        n     = bar.n;
    const auto                       &M     = bar.M;
    const auto                       &phi   = bar.phi;
    const double                      omega = bar.omega;
    const double                      T     = bar.T;
    const auto   modal = [&](const Vector<double> &u) { return bar.modal(u); };
    const double amplitude = 1e-3;

    // IDA over two periods, output every T/10
    SUNDIALS::IDA<Vector<double>>::AdditionalData data;
    data.initial_time       = 0.;
    data.final_time         = 2. * T;
    data.initial_step_size  = T / 1000.;
    data.output_period      = T / 10.;
    data.relative_tolerance = 1e-8;
    data.absolute_tolerance = 1e-12;
    data.ic_type    = SUNDIALS::IDA<Vector<double>>::AdditionalData::none;
    data.reset_type = SUNDIALS::IDA<Vector<double>>::AdditionalData::none;
    Dynamics::TimeIntegrator::Parameters p;
    Dynamics::IdaIntegrator              ida(data, p, sim, M);
    Dynamics::State                      s;
    s.u = phi;
    s.u *= amplitude;
    s.v.reinit(n);
    std::vector<std::pair<double, double>> ida_q;
    const unsigned int steps = ida.integrate(s, [&](const Dynamics::State &o) {
      ida_q.emplace_back(o.t, modal(o.u));
    });
    double             err_exact = 0.;
    for (const auto &[t, q] : ida_q)
      err_exact =
        std::max(err_exact, std::abs(q - amplitude * std::cos(omega * t)));

    // Newmark with T/100 at the same output times
    p.scheme = Dynamics::Scheme::newmark;
    Dynamics::TimeIntegrator newmark(p, sim, &M, nullptr);
    Dynamics::State          sn;
    sn.u = phi;
    sn.u *= amplitude;
    sn.v.reinit(n);
    newmark.initialize(sn);
    double       err_newmark = 0., next = 0.;
    unsigned int k = 0;
    for (unsigned int i = 1; i <= 200; ++i)
      {
        newmark.step(sn, T / 100., next);
        if (i % 10 == 0 && ++k < ida_q.size())
          err_newmark =
            std::max(err_newmark, std::abs(modal(sn.u) - ida_q[k].second));
      }
    deallog << "oscillator, 2 periods: IDA (rtol 1e-8) " << steps
            << " outputs, " << ida.n_jacobian_setups
            << " Jacobian setups; max |q_IDA - A cos(omega t)| / A "
            << error_bound(err_exact / amplitude, -8)
            << ", max |q_IDA - q_Newmark(T/100)| / A "
            << error_bound(err_newmark / amplitude, -6)
            << " (Newmark's phase error 2 pi (omega dt)^2 / 12 per period = "
            << std::setprecision(2)
            << 2. * numbers::PI * std::pow(2. * numbers::PI / 100., 2) / 12.
            << std::setprecision(6) << ")" << std::endl;
  }


  void
  falling_block()
  {
    // the block's mean height (z displacement) after the first impact, by
    // IDA and by Newmark with a small step
    DynamicsTestScenes::FallingBlock block;
    auto                            &sim    = block.sim;
    const auto                       n      = block.n;
    const auto                      &M      = block.M;
    const auto                       mean_z = [&](const Vector<double> &u) {
      return block.mean_height(u);
    };
    Dynamics::TimeIntegrator::Parameters p;
    p.rayleigh_alpha = 5.;

    SUNDIALS::IDA<Vector<double>>::AdditionalData data;
    data.final_time         = 0.3;
    data.initial_step_size  = 1e-4;
    data.output_period      = 0.05;
    data.relative_tolerance = 1e-6;
    data.absolute_tolerance = 1e-9;
    data.ic_type    = SUNDIALS::IDA<Vector<double>>::AdditionalData::none;
    data.reset_type = SUNDIALS::IDA<Vector<double>>::AdditionalData::none;
    Dynamics::IdaIntegrator ida(data, p, sim, M);
    Dynamics::State         s;
    s.u.reinit(n);
    s.v.reinit(n);
    std::vector<double> z_ida;
    ida.integrate(s, [&](const Dynamics::State &o) {
      z_ida.push_back(mean_z(o.u));
    });

    p.scheme = Dynamics::Scheme::newmark;
    Dynamics::TimeIntegrator newmark(p, sim, &M, nullptr);
    Dynamics::State          sn;
    sn.u.reinit(n);
    sn.v.reinit(n);
    newmark.initialize(sn);
    double       err = 0., next = 0., scale = 0.;
    unsigned int k = 0;
    for (unsigned int i = 1; i <= 600; ++i)
      {
        newmark.step(sn, 5e-4, next);
        if (i % 100 == 0 && ++k < z_ida.size())
          {
            err   = std::max(err, std::abs(mean_z(sn.u) - z_ida[k]));
            scale = std::max(scale, std::abs(z_ida[k]));
          }
      }
    deallog << "falling block to t = 0.3 (through the impact): max |z_IDA - "
               "z_Newmark(5e-4)| / max |z| "
            << error_bound(err / scale, -6) << ", " << ida.n_jacobian_setups
            << " Jacobian setups" << std::endl;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  oscillator();
  falling_block();
}
