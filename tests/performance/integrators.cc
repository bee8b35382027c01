// Benchmark (not a test): the speed/accuracy trade of the time integrators
// on the falling rods (prm/falling_rods.prm on the 2 x 2 array of
// meshes/falling_rods_2x2.msh, as tests/dynamics/falling_rods): the lower
// rods hit the rigid curved bar at t = 0.15, the upper rods hit the lower
// ones at t = 0.25. For each integrator and step: wall time per step and
// per simulated second, and the error of the rods' down-slope tip
// deflections at t = 0.1, 0.2, 0.3, 0.4 against Newmark with dt = 1e-3
// (largest over rods and times, in rod radii). Writes integrators.csv and,
// with gnuplot, integrators.png (error against cost) in the current folder.
//
//   cmake --build build --target performance
//   build/tests/performance/integrators

#include "dynamics/scenes.h"
#include "tests.h"

#include <tissue_contact/dynamics/ida_integrator.h>
#include <tissue_contact/dynamics/time_integrator.h>

#include <deal.II/base/timer.h>

#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>

using namespace dealii;
using namespace TissueContact;

namespace
{
  struct Run
  {
    std::string                      name;
    double                           dt      = 0.;
    unsigned int                     steps   = 0;
    double                           seconds = 0.;
    std::vector<std::vector<double>> tips; // at t = 0.1, 0.2, 0.3, 0.4
  };
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                prm = TissueContactTests::project_prm(
    "falling_rods.prm", {{"falling_rods.msh", "falling_rods_2x2.msh"}});
  const auto           parameters = Scene::SceneParameters::from_string(prm);
  std::ostringstream   log;
  Problem              sim(parameters);
  const auto           n = sim.n_dofs();
  SparseMatrix<double> M(sim.discretization().sparsity_pattern);
  Dynamics::assemble_consistent_mass(sim.discretization(),
                                     sim.get_scene().body_data(),
                                     M);
  const Vector<double> M_lumped =
    Dynamics::lumped_mass(sim.discretization(), sim.get_scene().body_data());
  const DynamicsTestScenes::RodTips tips(sim.discretization());
  const auto                        deflections = [&](const Vector<double> &u) {
    std::vector<double> d;
    for (unsigned int k = 0; k < tips.centres.size(); ++k)
      d.push_back(tips.deflection(u, k));
    return d;
  };
  const double end_time = 0.4, sample = 0.1;

  const Dynamics::TimeIntegrator::Parameters base = parameters.time_integration;
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
      &M_lumped,
      parameters.solver);
    Dynamics::State s;
    s.u.reinit(n);
    s.v.reinit(n);
    integrator.initialize(s);
    Timer  timer;
    double next = dt, target = sample;
    try
      {
        while (s.t < end_time - 1e-12)
          {
            integrator.step(s, std::min(dt, target - s.t), next);
            ++r.steps;
            if (s.t >= target - 1e-12)
              {
                r.tips.push_back(deflections(s.u));
                target += sample;
              }
          }
      }
    catch (const std::exception &)
      {
        r.name += " (FAILED)";
        r.tips.clear();
      }
    r.seconds = timer.wall_time();
    return r;
  };
  const auto ida = [&](const double tolerance) {
    SUNDIALS::IDA<Vector<double>>::AdditionalData data;
    data.final_time        = end_time;
    data.initial_step_size = 1e-4;
    // outputs every 0.01 (IDA allows 500 steps per output interval; the
    // impacts need more in 0.1), sampled every 0.1
    data.output_period      = 0.01;
    data.relative_tolerance = tolerance;
    // the rods' displacements are ~0.1 and velocities ~1: an absolute
    // tolerance below 1e-3 makes IDA resolve the high-frequency response
    // to the suddenly applied gravity, at steps of ~1e-4 (doc/theory/06,
    // sec. 8)
    data.absolute_tolerance = 1e-3;
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
          const double k = std::round(o.t / sample);
          if (k > 0.5 && std::abs(o.t - k * sample) < 1e-9)
            r.tips.push_back(deflections(o.u));
        });
      }
    catch (const std::exception &)
      {
        r.name += " (FAILED)";
        r.tips.clear();
      }
    r.seconds = timer.wall_time();
    r.steps   = integrator.n_jacobian_setups;
    return r;
  };

  const Run reference = stepping("reference", Dynamics::Scheme::newmark, 1e-3);
  const double estimate =
    Dynamics::stable_time_step_estimate(sim.discretization(),
                                        sim.get_scene().body_data());
  std::vector<Run> runs;
  for (const double dt : {2e-2, 1e-2, 5e-3, 2.5e-3})
    runs.push_back(stepping("Newmark", Dynamics::Scheme::newmark, dt));
  for (const double dt : {2e-2, 1e-2, 5e-3, 2.5e-3})
    runs.push_back(
      stepping("implicit Euler", Dynamics::Scheme::implicit_euler, dt));
  for (const double f : {0.9, 0.45})
    runs.push_back(stepping("central difference",
                            Dynamics::Scheme::central_difference,
                            f * estimate));
  for (const double tolerance : {1e-3, 1e-4})
    runs.push_back(ida(tolerance));

  std::cout << "Falling rods, 2 x 2 array ("
            << sim.get_scene().triangulation.n_active_cells()
            << " tetrahedra, P1, " << n << " unknowns), t = 0.." << end_time
            << ": rods on the bar at 0.15, rod on rod at 0.25; "
            << MultithreadInfo::n_threads()
            << " thread(s)\n"
               "error: max over rods and t = 0.1, 0.2, 0.3, 0.4 of |tip "
               "deflection - Newmark(1e-3)| / rod radius\n\n"
            << std::left << std::setw(27) << "integrator" << std::setw(11)
            << "step" << std::setw(8) << "steps" << std::setw(13) << "ms / step"
            << std::setw(16) << "s / sim. second"
            << "error\n";
  std::ofstream csv("integrators.csv");
  csv << "key,step,steps,seconds,seconds_per_simulated_second,error\n";
  for (const auto &r : runs)
    {
      double error = r.tips.size() < reference.tips.size() ?
                       std::numeric_limits<double>::infinity() :
                       0.;
      for (unsigned int k = 0; k < r.tips.size() && k < reference.tips.size();
           ++k)
        for (unsigned int j = 0; j < r.tips[k].size(); ++j)
          error = std::max(error,
                           std::abs(r.tips[k][j] - reference.tips[k][j]) /
                             tips.radius);
      std::cout << std::setw(27) << r.name << std::setw(11)
                << (r.dt > 0. ? std::to_string(r.dt).substr(0, 8) : "adaptive")
                << std::setw(8) << r.steps << std::setw(13)
                << std::setprecision(3) << 1e3 * r.seconds / r.steps
                << std::setw(16) << r.seconds / end_time << error << "\n";
      const std::string key = r.name.substr(0, r.name.find(' ')) == "IDA" ?
                                "IDA" :
                              r.name == "implicit Euler"     ? "Euler" :
                              r.name == "central difference" ? "explicit" :
                                                               "Newmark";
      if (std::isfinite(error))
        csv << key << ',' << r.dt << ',' << r.steps << ',' << r.seconds << ','
            << r.seconds / end_time << ',' << error << "\n";
    }
  std::cout << "(IDA: 'steps' counts Jacobian setups; central difference at "
               "0.9 and 0.45 of the stable estimate "
            << estimate << ")\n";
  csv.close();
  if (std::system("command -v gnuplot > /dev/null 2>&1") == 0)
    {
      std::ofstream gp("integrators.gp");
      gp << "set terminal pngcairo size 900,650 font ',11'\n"
            "set output 'integrators.png'\n"
            "set datafile separator ','\n"
            "set logscale xy\n"
            "set xlabel 'wall time per simulated second [s]'\n"
            "set ylabel 'error of the tip deflections / rod radius'\n"
            "set title 'Falling rods: the integrators trade cost for "
            "accuracy'\n"
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
