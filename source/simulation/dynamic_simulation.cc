#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/base/interrupt.h>
#include <tissue_contact/base/memory_usage.h>
#include <tissue_contact/dynamics/ida_integrator.h>
#include <tissue_contact/dynamics/mass_matrix.h>
#include <tissue_contact/simulation/dynamic_simulation.h>
#include <tissue_contact/simulation/result_writer.h>

#include <deal.II/base/timer.h>

#include <filesystem>
#include <fstream>
#include <iomanip>

namespace TissueContact
{
  DynamicSimulation::DynamicSimulation(const Scene::SceneParameters &parameters,
                                       std::ostream                 &out)
    : out(out)
    , nonlinear_problem(parameters)
  {
    AssertThrow(nonlinear_problem.free_rigid_bodies() == nullptr,
                ExcMessage("free rigid bodies (Rigid motion/Free = true) are "
                           "supported in static runs only (Time "
                           "integration/Scheme = static): their inertia is "
                           "not modelled"));
    const auto &disc   = nonlinear_problem.discretization();
    const auto  bodies = nonlinear_problem.get_scene().body_data();
    const auto &ti     = parameters.time_integration;
    M_lumped           = Dynamics::lumped_mass(disc, bodies);
    // every deformable body needs mass: a massless node has no
    // acceleration in the explicit scheme and makes the implicit ones'
    // inertia singular where the stiffness vanishes
    for (const auto &b : parameters.bodies)
      AssertThrow(b.material.model == "rigid" || b.density > 0.,
                  ExcMessage("body '" + b.name +
                             "' has Density 0: a dynamic analysis needs "
                             "mass in every deformable body; give it its "
                             "density (or run it static: Time "
                             "integration/Analysis = static)"));
    if (!ti.lumped_mass && ti.scheme != Dynamics::Scheme::central_difference)
      {
        M.reinit(disc.sparsity_pattern);
        Dynamics::assemble_consistent_mass(disc, bodies, M);
      }
  }


  std::ofstream
  DynamicSimulation::open_time_history(const std::string &columns,
                                       std::string       &name,
                                       const bool         append) const
  {
    const auto &o = nonlinear_problem.get_scene().parameters.output;
    std::filesystem::create_directories(o.directory);
    name = o.directory + "/" + o.base_name + "-time.csv";
    std::ofstream csv(name, append ? std::ios::app : std::ios::trunc);
    AssertThrow(csv.good(),
                ExcMessage("cannot write the time history '" + name + "'"));
    if (!append)
      csv << columns << "\n";
    return csv;
  }


  void
  DynamicSimulation::run(
    const std::function<void(const Dynamics::TimeIntegrator &,
                             const Dynamics::State &,
                             const Dynamics::State &)> &on_step,
    const Checkpoint                                   *restart)
  {
    const auto &p    = nonlinear_problem.get_scene().parameters;
    const auto &ti   = p.time_integration;
    const auto &disc = nonlinear_problem.discretization();
    Timer       timer;

    const std::string scheme = Dynamics::scheme_name(ti.scheme);
    out << "TissueContact dynamic analysis\n"
        << "  mesh: "
        << nonlinear_problem.get_scene().triangulation.n_active_cells()
        << " tetrahedra; P" << p.degree << " elements, " << disc.n_dofs()
        << " unknowns\n"
        << "  scheme: " << scheme << ", time step " << ti.time_step
        << ", end time " << ti.end_time << ", "
        << (M.empty() ? "lumped" : "consistent") << " mass "
        << M_lumped.mean_value() * M_lumped.size() / 3. << "\n";
    for (const auto &w : nonlinear_problem.warnings())
      out << "  warning: " << w << "\n";
    if (ti.scheme == Dynamics::Scheme::central_difference)
      {
        const double estimate = Dynamics::stable_time_step_estimate(
          disc, nonlinear_problem.get_scene().body_data());
        out << "  stable step estimate (smallest altitude / wave speed): "
            << estimate << " (keep the step below 0.9 of it)"
            << (ti.time_step > 0.9 * estimate ?
                  " -- the time step is above: the run may be stopped as "
                  "unstable" :
                  "")
            << "\n";
      }

    if (ti.scheme == Dynamics::Scheme::ida)
      {
        AssertThrow(restart == nullptr,
                    ExcMessage("a run with Scheme = IDA cannot be restarted: "
                               "IDA's multistep history is not in the "
                               "checkpoint; restart with Newmark or implicit "
                               "Euler, or run it again"));
        run_ida();
        return;
      }
    Dynamics::TimeIntegrator integrator(
      ti, nonlinear_problem, M.empty() ? nullptr : &M, &M_lumped, p.solver);
    s.u.reinit(disc.n_dofs());
    s.v.reinit(disc.n_dofs());
    s.t = 0.;
    integrator.initialize(s);
    // the time spent, by section, printed at the end like the static run's
    TimerOutput timer_output(out,
                             p.output.print_timing ? TimerOutput::summary :
                                                     TimerOutput::never,
                             TimerOutput::wall_times);
    integrator.set_timer(&timer_output);
    nonlinear_problem.set_timer(&timer_output);

    // one column per contact interaction: pairs as contact_<surface body>_
    // <volume body>, obstacles as obstacle_<index>
    std::string columns =
      "step,time,time_step,newton_iterations,kinetic_energy,energy,"
      "dissipated";
    for (const auto &pair : p.contact.pairs)
      columns += ",contact_" + std::to_string(pair.surface_body) + "_" +
                 std::to_string(pair.volume_body);
    for (unsigned int i = 0; i < p.contact.obstacles.size(); ++i)
      columns += ",obstacle_" + std::to_string(i);
    ResultWriter  results(nonlinear_problem, restart);
    std::string   csv_name;
    std::ofstream csv =
      open_time_history(columns, csv_name, restart != nullptr);

    unsigned int step = 0, cutbacks = 0, iterations = 0, lu_solves = 0;
    double       dt = ti.time_step, next_output = ti.output_interval;
    double       dissipated = 0., t_start = 0.;
    if (restart != nullptr)
      {
        AssertThrow(restart->kind == "dynamic",
                    ExcMessage("the checkpoint is of a " + restart->kind +
                               " run; this scene is dynamic"));
        const auto n = disc.n_dofs();
        s.u          = restart->vector("u", n);
        s.v          = restart->vector("v", n);
        s.a          = restart->vector("a", n);
        s.t          = restart->scalar("t");
        step         = restart->step;
        cutbacks     = restart->scalar("cutbacks");
        iterations   = restart->scalar("newton_iterations");
        // absent from checkpoints written before it was counted
        if (restart->scalars.count("lu_solves") > 0)
          lu_solves = restart->scalar("lu_solves");
        dt          = restart->scalar("dt");
        next_output = restart->scalar("next_output");
        dissipated  = restart->scalar("dissipated");
        integrator.restore_blow_up_reference(
          {restart->scalar("reference_energy"),
           restart->scalar("first_step_done") != 0.});
        t_start = s.t;
        out << "Restarted from the checkpoint after step " << step
            << " (t = " << s.t << ")" << std::endl;
      }
    else
      results.record(0, s.t, s.u, integrator.load_factor(s.t), true);

    out << "  step     time         dt           Newton  kinetic energy\n";
    Vector<double> v_mid(disc.n_dofs()), Cv(disc.n_dofs());
    try
      {
        while (s.t < ti.end_time * (1. - 1e-12))
          {
            const double          request = std::min(dt, ti.end_time - s.t);
            double                next    = request;
            const Dynamics::State before  = s;
            const double          taken   = integrator.step(s, request, next);
            cutbacks += (taken < request);
            iterations += integrator.last_iterations;
            lu_solves += integrator.last_lu_solves;
            dt = std::max(next, taken);
            ++step;
            const double        kinetic = integrator.kinetic_energy(s);
            std::vector<double> contact_energies;
            const double        energy =
              kinetic + nonlinear_problem.energy(s.u,
                                                 integrator.load_factor(s.t),
                                                 contact_energies);
            // the damping's work over the step at the mid-step velocity
            // (exact for the average-acceleration Newmark scheme)
            v_mid = before.v;
            v_mid += s.v;
            v_mid *= 0.5;
            integrator.damping().vmult(Cv, v_mid);
            dissipated += taken * (v_mid * Cv);
            csv << step << ',' << s.t << ',' << taken << ','
                << integrator.last_iterations << ',' << kinetic << ',' << energy
                << ',' << dissipated;
            for (const double W : contact_energies)
              csv << ',' << W;
            csv << std::endl; // readable while the run goes on
            if (on_step)
              on_step(integrator, before, s);
            out << std::setw(6) << step << std::scientific
                << std::setprecision(4) << std::setw(13) << s.t << std::setw(13)
                << taken << std::setw(6) << integrator.last_iterations << "  "
                << kinetic << std::defaultfloat << std::setprecision(6);
            // progress: wall time, and the time left extrapolated linearly
            // in the simulated time
            if (p.output.print_timing)
              out << std::fixed << std::setprecision(1) << "  "
                  << timer.wall_time() << " s, about "
                  << timer.wall_time() * (ti.end_time - s.t) / (s.t - t_start)
                  << " s left" << std::defaultfloat << std::setprecision(6);
            out << std::endl;
            {
              TimerOutput::Scope scope(timer_output, "output");
              const bool         vtu_due =
                s.t >= ti.end_time * (1. - 1e-12) ||
                (ti.output_interval > 0. ? s.t >= next_output * (1. - 1e-12) :
                                           results.due(step));
              results.record(step,
                             s.t,
                             s.u,
                             integrator.load_factor(s.t),
                             vtu_due,
                             {{"kinetic_energy", kinetic}, {"energy", energy}});
              if (vtu_due)
                next_output = s.t + ti.output_interval;
              if (s.t < ti.end_time * (1. - 1e-12) &&
                  results.checkpoint_due(step))
                {
                  Checkpoint c;
                  c.kind               = "dynamic";
                  c.step               = step;
                  const auto reference = integrator.blow_up_reference();
                  c.scalars            = {{"t", s.t},
                                          {"dt", dt},
                                          {"cutbacks", cutbacks},
                                          {"newton_iterations", iterations},
                                          {"lu_solves", lu_solves},
                                          {"next_output", next_output},
                                          {"dissipated", dissipated},
                                          {"reference_energy", reference.first},
                                          {"first_step_done", reference.second}};
                  c.vectors            = {{"u", s.u}, {"v", s.v}, {"a", s.a}};
                  results.write_checkpoint(c,
                                           {results.statistics_file(),
                                            csv_name});
                }
            }
            // a signal received meanwhile stops the run here, every file
            // complete
            check_interrupt();
          }
        results.finish();
      }
    catch (const std::exception &e)
      {
        nonlinear_problem.set_timer(nullptr);
        const std::string kept =
          "; the steps up to t = " + Utilities::to_string(s.t) +
          " are kept in " +
          (p.output.write_vtu ? results.pvd_file() + " and " : "") +
          results.statistics_file();
        if (const auto *i = dynamic_cast<const Interrupted *>(&e))
          throw Interrupted(i->signal, kept);
        AssertThrow(false, ExcMessage(error_message(e) + kept));
      }
    nonlinear_problem.set_timer(nullptr);
    out << "Reached t = " << s.t << " in " << step << " steps (" << cutbacks
        << " cut back), " << iterations << " Newton iterations"
        << cholesky_fallback_summary(lu_solves)
        << (p.output.print_timing ?
              ", " + std::to_string(timer.wall_time()) + " s wall time" :
              std::string())
        << "\n"
        << "  time history: " << csv_name << "\n"
        << "  statistics: " << results.statistics_file() << "\n";
    if (p.output.write_vtu)
      out << "  results: " << results.pvd_file() << " (open in ParaView)\n";
    if (p.output.print_timing)
      {
        // where the resident memory goes (base/memory_usage.h)
        const std::string memory = memory_summary();
        if (!memory.empty())
          out << "  " << memory << "\n";
      }
  }
} // namespace TissueContact


namespace TissueContact
{
  void
  DynamicSimulation::run_ida()
  {
    const auto &p    = nonlinear_problem.get_scene().parameters;
    const auto &ti   = p.time_integration;
    const auto &disc = nonlinear_problem.discretization();
    AssertThrow(!M.empty(),
                ExcMessage("Time integration: IDA needs the consistent mass "
                           "(Mass = consistent)"));
    Dynamics::IdaIntegrator ida(ti.ida_data(), ti, nonlinear_problem, M);
    s.u.reinit(disc.n_dofs());
    s.v.reinit(disc.n_dofs());
    s.t = 0.;

    ResultWriter  results(nonlinear_problem);
    std::string   csv_name;
    std::ofstream csv =
      open_time_history("output,time,kinetic_energy", csv_name);
    out << "  output   time         kinetic energy\n";
    unsigned int outputs = 0;
    try
      {
        ida.integrate(s, [&](const Dynamics::State &o) {
          Vector<double> Mv(o.v.size());
          M.vmult(Mv, o.v);
          const double kinetic = 0.5 * (o.v * Mv);
          csv << outputs << ',' << o.t << ',' << kinetic << std::endl;
          out << std::setw(8) << outputs << std::scientific
              << std::setprecision(4) << std::setw(13) << o.t << "  " << kinetic
              << std::defaultfloat << std::setprecision(6) << "\n";
          results.record(outputs,
                         o.t,
                         o.u,
                         ti.ramp_time > 0. ? std::min(1., o.t / ti.ramp_time) :
                                             1.,
                         true,
                         {{"kinetic_energy", kinetic}});
          ++outputs;
          check_interrupt();
        });
        results.finish();
      }
    catch (const Interrupted &i)
      {
        throw Interrupted(i.signal,
                          "; the outputs so far are kept in " +
                            (p.output.write_vtu ? results.pvd_file() + " and " :
                                                  std::string()) +
                            results.statistics_file());
      }
    catch (const std::exception &e)
      {
        AssertThrow(false,
                    ExcMessage("IDA failed: " + error_message(e) +
                               "; the outputs so far are kept in " +
                               (p.output.write_vtu ?
                                  results.pvd_file() + " and " :
                                  std::string()) +
                               results.statistics_file()));
      }
    out << "Reached t = " << s.t << " (IDA: " << ida.n_jacobian_setups
        << " Jacobian setups)\n"
        << "  time history: " << csv_name << "\n"
        << "  statistics: " << results.statistics_file() << "\n";
    if (p.output.write_vtu)
      out << "  results: " << results.pvd_file() << " (open in ParaView)\n";
    if (p.output.print_timing)
      {
        // where the resident memory goes (base/memory_usage.h)
        const std::string memory = memory_summary();
        if (!memory.empty())
          out << "  " << memory << "\n";
      }
  }
} // namespace TissueContact
