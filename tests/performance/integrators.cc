// Benchmark (not a test): the speed/accuracy trade of the time integrators
// on the block dropped onto a rigid plane (tests/dynamics/scenes.h; the
// falling-rods scene of issue 4 is not built yet). For each integrator and
// step: wall time per step and per simulated second, and the error of the
// block's mean height at t = 0.1, 0.2, 0.3 (through the impact) against
// Newmark with dt = 1e-4. Writes integrators.csv and, with gnuplot,
// integrators.png (error against cost) in the current folder.
//
//   cmake --build build --target performance
//   build/tests/performance/integrators

#include "dynamics/scenes.h"

#include <deal.II/base/timer.h>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <tissue_contact/dynamics/ida_integrator.h>
#include <tissue_contact/dynamics/time_integrator.h>

using namespace dealii;
using namespace TissueContact;

namespace
{
  struct Run
  {
    std::string         name;
    double              dt      = 0.;
    unsigned int        steps   = 0;
    double              seconds = 0.;
    std::vector<double> heights; // at t = 0.1, 0.2, 0.3
  };
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  DynamicsTestScenes::FallingBlock block;
  auto                            &sim = block.sim;
  const auto                       n   = block.n;
  const auto                      &M   = block.M;
  const Vector<double>             M_lumped =
    Dynamics::lumped_mass(sim.discretization(), sim.get_scene().body_data());
  const auto height = [&](const Vector<double> &u) {
    return block.mean_height(u);
  };

  Dynamics::TimeIntegrator::Parameters base;
  base.rayleigh_alpha = 5.;
  const auto stepping = [&](const std::string     &name,
                            const Dynamics::Scheme scheme,
                            const double           dt) {
    Run                                  r{name, dt};
    Dynamics::TimeIntegrator::Parameters p = base;
    p.scheme                               = scheme;
    Dynamics::TimeIntegrator integrator(
      p,
      sim,
      scheme == Dynamics::Scheme::central_difference ? nullptr : &M,
      &M_lumped);
    Dynamics::State s;
    s.u.reinit(n);
    s.v.reinit(n);
    integrator.initialize(s);
    Timer  timer;
    double next = dt, target = 0.1;
    while (s.t < 0.3 - 1e-12)
      {
        integrator.step(s, std::min(dt, target - s.t), next);
        ++r.steps;
        if (s.t >= target - 1e-12)
          {
            r.heights.push_back(height(s.u));
            target += 0.1;
          }
      }
    r.seconds = timer.wall_time();
    return r;
  };
  const auto ida = [&](const double tolerance) {
    SUNDIALS::IDA<Vector<double>>::AdditionalData data;
    data.final_time         = 0.3;
    data.initial_step_size  = 1e-4;
    data.output_period      = 0.1;
    data.relative_tolerance = tolerance;
    data.absolute_tolerance = 1e-3 * tolerance;
    data.ic_type    = SUNDIALS::IDA<Vector<double>>::AdditionalData::none;
    data.reset_type = SUNDIALS::IDA<Vector<double>>::AdditionalData::none;
    std::ostringstream name;
    name << "IDA rtol " << tolerance;
    Run                     r{name.str(), 0.};
    Dynamics::IdaIntegrator integrator(data, base, sim, M);
    Dynamics::State         s;
    s.u.reinit(n);
    s.v.reinit(n);
    Timer timer;
    try
      {
        integrator.integrate(s, [&](const Dynamics::State &o) {
          if (o.t > 1e-12)
            r.heights.push_back(height(o.u));
        });
      }
    catch (const std::exception &)
      {
        r.name += " (FAILED)";
        r.heights.clear();
      }
    r.seconds = timer.wall_time();
    r.steps   = integrator.n_jacobian_setups;
    return r;
  };

  const Run reference = stepping("reference", Dynamics::Scheme::newmark, 1e-4);
  const double estimate =
    Dynamics::stable_time_step_estimate(sim.discretization(),
                                        sim.get_scene().body_data());
  std::vector<Run> runs;
  for (const double dt : {8e-3, 4e-3, 2e-3, 1e-3})
    runs.push_back(stepping("Newmark", Dynamics::Scheme::newmark, dt));
  for (const double dt : {8e-3, 4e-3, 2e-3, 1e-3})
    runs.push_back(
      stepping("implicit Euler", Dynamics::Scheme::implicit_euler, dt));
  for (const double f : {0.9, 0.45})
    runs.push_back(stepping("central difference",
                            Dynamics::Scheme::central_difference,
                            f * estimate));
  for (const double tolerance : {1e-3, 1e-4, 1e-5, 1e-6})
    runs.push_back(ida(tolerance));

  std::cout << "Falling block (48 tetrahedra, P1, 81 unknowns), t = 0..0.3 "
               "through the impact, 1 thread\n"
               "error: max over t = 0.1, 0.2, 0.3 of |mean height - "
               "Newmark(1e-4)| / drop height 0.1\n\n"
            << std::left << std::setw(27) << "integrator" << std::setw(11)
            << "step" << std::setw(8) << "steps" << std::setw(13) << "ms / step"
            << std::setw(16) << "s / sim. second"
            << "error\n";
  std::ofstream csv("integrators.csv");
  csv << "key,step,steps,seconds,seconds_per_simulated_second,error\n";
  for (const auto &r : runs)
    {
      double error =
        r.heights.size() < 3 ? std::numeric_limits<double>::infinity() : 0.;
      for (unsigned int k = 0; k < r.heights.size() && k < 3; ++k)
        error =
          std::max(error, std::abs(r.heights[k] - reference.heights[k]) / 0.1);
      std::cout << std::setw(27) << r.name << std::setw(11)
                << (r.dt > 0. ? std::to_string(r.dt).substr(0, 8) : "adaptive")
                << std::setw(8) << r.steps << std::setw(13)
                << std::setprecision(3) << 1e3 * r.seconds / r.steps
                << std::setw(16) << r.seconds / 0.3 << error << "\n";
      const std::string key = r.name.substr(0, r.name.find(' ')) == "IDA" ?
                                "IDA" :
                              r.name == "implicit Euler"     ? "Euler" :
                              r.name == "central difference" ? "explicit" :
                                                               "Newmark";
      if (std::isfinite(error))
        csv << key << ',' << r.dt << ',' << r.steps << ',' << r.seconds << ','
            << r.seconds / 0.3 << ',' << error << "\n";
    }
  std::cout << "(IDA: 'steps' counts Jacobian setups; central difference at "
               "0.9 and 0.45 of the stable estimate "
            << estimate << ")\n";
  csv.close();
  if (std::system("command -v gnuplot > /dev/null 2>&1") == 0)
    {
      std::ofstream gp("integrators.gp");
      gp
        << "set terminal pngcairo size 900,650 font ',11'\n"
           "set output 'integrators.png'\n"
           "set datafile separator ','\n"
           "set logscale xy\n"
           "set xlabel 'wall time per simulated second [s]'\n"
           "set ylabel 'error of the mean height / drop height'\n"
           "set title 'Falling block: the integrators trade cost for accuracy'\n"
           "set key bottom left\n"
           "keys = 'Newmark Euler explicit IDA'\n"
           "titles = '\"Newmark\" \"implicit Euler\" \"central difference\" "
           "\"IDA\"'\n"
           "plot for [i=1:4] 'integrators.csv' using (strcol(1) eq "
           "word(keys, i) ? $5 : 1/0):6 with linespoints lw 2 title "
           "word(titles, i) noenhanced\n";
      gp.close();
      if (std::system("gnuplot integrators.gp") == 0)
        std::cout << "wrote integrators.csv and integrators.png\n";
    }
}
