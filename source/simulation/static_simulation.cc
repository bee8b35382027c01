#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/base/interrupt.h>
#include <tissue_contact/base/memory_usage.h>
#include <tissue_contact/output/convergence_log.h>
#include <tissue_contact/simulation/result_writer.h>
#include <tissue_contact/simulation/static_simulation.h>

#include <iomanip>
#include <memory>
#include <sstream>


namespace TissueContact
{
  StaticSimulation::StaticSimulation(const Scene::SceneParameters &parameters,
                                     std::ostream                 &out)
    : nonlinear_problem(parameters)
    , u(nonlinear_problem.n_dofs())
    , out(out)
  {}


  SolveStatistics
  StaticSimulation::solve_quietly(
    const std::function<void(const IterationInfo &)> &on_iteration)
  {
    Solvers::IncrementalNewtonSolver solver(
      nonlinear_problem.get_scene().parameters.solver);
    solver.on_iteration              = on_iteration;
    u                                = 0.;
    const SolveStatistics statistics = solver.solve(nonlinear_problem, u);
    nonlinear_problem.complete(u);
    return statistics;
  }


  SolveStatistics
  StaticSimulation::run(const Checkpoint *restart)
  {
    const auto &scene     = nonlinear_problem.get_scene();
    const auto &p         = scene.parameters;
    const auto &disc      = nonlinear_problem.discretization();
    const auto &assembler = nonlinear_problem.elastic_assembler();
    const auto *contact   = nonlinear_problem.contact_assembler();
    Timer       total;
    TimerOutput timer(out,
                      p.output.print_timing ? TimerOutput::summary :
                                              TimerOutput::never,
                      TimerOutput::wall_times);

    out << "TissueContact static analysis\n"
        << "  mesh: " << scene.triangulation.n_active_cells() << " tetrahedra, "
        << scene.triangulation.n_vertices() << " vertices; P" << p.degree
        << " elements, " << disc.n_dofs() << " unknowns, "
        << nonlinear_problem.n_prescribed() << " prescribed\n";
    for (const auto &b : p.bodies)
      out << "  body '" << b.name << "' (material id " << int(b.id)
          << "): " << b.material.model << (b.material.fiber ? " + fibers" : "")
          << "\n";
    const double widening = nonlinear_problem.pattern_widening();
    const auto   linear =
      p.solver.linear_solver.resolved(nonlinear_problem.n_dofs(), widening);
    std::ostringstream limit;
    if (widening > 1.05)
      limit << nonlinear_problem.n_dofs() << " unknowns weighted by "
            << std::setprecision(2) << widening
            << "^2, the tangent's entries over the element couplings': ";
    limit << (linear.type == "direct" ? "below " : "at least ")
          << linear.automatic_limit << " unknowns";
    out << "  linear solver: " << linear.type
        << (linear.type == "direct" ? " (" + linear.direct_solver + ")" : "")
        << (p.solver.linear_solver.type == "automatic" ?
              ", chosen by Type = automatic (" + limit.str() + ")" :
              std::string())
        << "\n";
    if (linear.type == "direct" && nonlinear_problem.n_dofs() > 20000)
      out << "  warning: a direct solver at " << nonlinear_problem.n_dofs()
          << " unknowns costs seconds per Newton iteration (measured on two "
             "cores at 27 783 unknowns: UMFPACK's LU 1.7 s, MUMPS' 1.1 s, the "
             "Cholesky factorization of a positive definite tangent about "
             "half UMFPACK's time; 5.4-6.1 s by LU on the 29 706 of the knee "
             "with its contact couplings); Linear solver/Type = GMRES+AMG "
             "(0.24 s at 27 783) may be faster\n";
    if (contact)
      out << "  contact: " << contact->n_triangles() << " contact triangles, "
          << p.contact.obstacles.size() << " obstacle(s), "
          << p.contact.pairs.size() << " body pair(s)\n";
    for (const auto &w : nonlinear_problem.warnings())
      out << "  warning: " << w << "\n";
    out.flush();

    ResultWriter      results(nonlinear_problem, restart);
    const std::string csv =
      p.output.directory + "/" + p.output.base_name + "-convergence.csv";
    Output::ConvergenceLog log(out, csv, restart != nullptr);

    Solvers::IncrementalNewtonSolver solver(p.solver);
    double                           lambda_start = 0.;
    solver.on_iteration = [&](const IterationInfo &i) {
      log.iteration(i);
      check_interrupt();
    };
    solver.on_cutback = [&](const double lambda, const std::string &why) {
      log.cutback(lambda, why);
    };
    // the results of the last converged increment, for the summary
    std::unique_ptr<StepResults> final_results;
    solver.on_increment = [&](const unsigned int    increment,
                              const double          lambda,
                              const Vector<double> &u) {
      TimerOutput::Scope scope(timer, "output");
      const bool         last = lambda >= 1. - 1e-12;
      final_results           = std::make_unique<StepResults>(
        results.record(increment,
                       lambda,
                       u,
                       lambda,
                       results.due(increment) || last,
                       {{"wall_time", total.wall_time()}}));
      if (!last && results.checkpoint_due(increment))
        {
          const auto &state = solver.load_state();
          Checkpoint  c;
          c.kind    = "static";
          c.step    = increment;
          c.scalars = {
            {"lambda", state.lambda},
            {"lambda_prev", state.lambda_prev},
            {"increment_size", state.increment_size},
            {"have_previous", state.have_previous},
            {"increments", state.statistics.increments},
            {"cutbacks", state.statistics.cutbacks},
            {"newton_iterations", state.statistics.newton_iterations},
            {"linear_iterations", state.statistics.linear_iterations},
            {"tangent_shifts", state.statistics.tangent_shifts},
            {"multiplier_updates", state.statistics.multiplier_updates},
            {"direct_fallbacks", state.statistics.direct_fallbacks},
            {"cholesky_fallbacks", state.statistics.cholesky_fallbacks}};
          c.vectors = {{"u", u}, {"u_prev", state.u_prev}};
          const std::vector<double> multipliers =
            nonlinear_problem.multipliers();
          if (!multipliers.empty())
            c.vectors["multipliers"] =
              Vector<double>(multipliers.begin(), multipliers.end());
          results.write_checkpoint(c, {results.statistics_file(), csv});
        }
      // progress: the time left extrapolated linearly in the load factor
      if (p.output.print_timing)
        {
          std::ostringstream line;
          // the load factor to the precision of the smallest increments
          line << std::fixed << std::setprecision(5)
               << "  converged at load factor " << lambda
               << std::setprecision(1) << " after " << total.wall_time()
               << " s";
          if (!last)
            line << "; about "
                 << total.wall_time() * (1. - lambda) / (lambda - lambda_start)
                 << " s left";
          out << line.str() << std::endl;
        }
      // a signal received meanwhile stops the run here, every file complete
      check_interrupt();
    };

    if (restart != nullptr)
      {
        AssertThrow(restart->kind == "static",
                    ExcMessage("the checkpoint is of a " + restart->kind +
                               " run; this scene is static"));
        const auto                                  n = u.size();
        Solvers::IncrementalNewtonSolver::LoadState state;
        state.lambda                = restart->scalar("lambda");
        state.lambda_prev           = restart->scalar("lambda_prev");
        state.increment_size        = restart->scalar("increment_size");
        state.have_previous         = restart->scalar("have_previous") != 0.;
        state.statistics.increments = restart->scalar("increments");
        state.statistics.cutbacks   = restart->scalar("cutbacks");
        state.statistics.newton_iterations =
          restart->scalar("newton_iterations");
        state.statistics.linear_iterations =
          restart->scalar("linear_iterations");
        state.statistics.tangent_shifts = restart->scalar("tangent_shifts");
        state.statistics.multiplier_updates =
          restart->scalar("multiplier_updates");
        // absent from checkpoints written before it was counted
        if (restart->scalars.count("direct_fallbacks") > 0)
          state.statistics.direct_fallbacks =
            restart->scalar("direct_fallbacks");
        if (restart->scalars.count("cholesky_fallbacks") > 0)
          state.statistics.cholesky_fallbacks =
            restart->scalar("cholesky_fallbacks");
        const auto n_multipliers = nonlinear_problem.multipliers().size();
        if (n_multipliers > 0)
          {
            const Vector<double> m =
              restart->vector("multipliers", n_multipliers);
            nonlinear_problem.set_multipliers(
              std::vector<double>(m.begin(), m.end()));
          }
        state.u_prev = restart->vector("u_prev", n);
        u            = restart->vector("u", n);
        solver.restart_from(state);
        lambda_start = state.lambda;
        out << "Restarted from the checkpoint after increment " << restart->step
            << " (load factor " << state.lambda << ")" << std::endl;
      }
    else
      {
        u = 0.;
        results.record(0, 0., u, 0., true, {{"wall_time", total.wall_time()}});
      }

    SolveStatistics statistics;
    try
      {
        nonlinear_problem.set_timer(&timer);
        statistics = solver.solve(nonlinear_problem, u, &timer);
        nonlinear_problem.set_timer(nullptr);
        nonlinear_problem.complete(u);
        results.finish();
      }
    catch (const std::exception &e)
      {
        nonlinear_problem.set_timer(nullptr);
        const std::string kept =
          "; the converged increments are kept in " +
          (p.output.write_vtu ? results.pvd_file() + " and " : "") +
          results.statistics_file();
        if (const auto *i = dynamic_cast<const Interrupted *>(&e))
          throw Interrupted(i->signal, kept);
        AssertThrow(false, ExcMessage(error_message(e) + kept));
      }

    const Vector<double> u_fe  = nonlinear_problem.displacement(u);
    double               u_max = 0.;
    for (const double v : u_fe)
      u_max = std::max(u_max, std::abs(v));
    out << "Converged: " << statistics.increments << " increments ("
        << statistics.cutbacks << " cut back), " << statistics.newton_iterations
        << " Newton iterations, " << statistics.linear_iterations
        << " linear iterations"
        << (statistics.tangent_shifts > 0 ?
              " (" + std::to_string(statistics.tangent_shifts) +
                " solves with a shifted tangent)" :
              std::string())
        << (statistics.rounding_convergences > 0 ?
              ", " + std::to_string(statistics.rounding_convergences) +
                " increments converged to rounding" :
              std::string())
        << (statistics.multiplier_updates > 0 ?
              ", " + std::to_string(statistics.multiplier_updates) +
                " augmented-Lagrangian updates" :
              std::string())
        << (statistics.direct_fallbacks > 0 ?
              ", " + std::to_string(statistics.direct_fallbacks) +
                " linear solves by the direct solver where GMRES+AMG did not "
                "converge" :
              std::string())
        << cholesky_fallback_summary(statistics.cholesky_fallbacks) << "\n"
        << "  max |u_i| = " << u_max
        << ", min J = " << assembler.min_jacobian(u_fe) << "\n"
        << "  convergence log: " << csv << "\n";
    for (const auto &w : nonlinear_problem.multiplier_warnings())
      out << "  warning: " << w << "\n";
    if (contact && !p.contact.obstacles.empty())
      out << "  obstacle force on the bodies " << contact->obstacle_force(u_fe)
          << ", max penetration " << contact->max_obstacle_penetration(u_fe)
          << "\n";
    if (contact && !p.contact.pairs.empty())
      out << "  penetration (largest material depth reached by a contact "
             "vertex inside a paired body): "
          << contact->max_body_penetration(u_fe) << ", at most "
          << nonlinear_problem.max_relative_penetration(u) * 100.
          << " % of the local element size\n";
    if (contact && p.contact.pairs.size() > 1)
      {
        const auto per_pair = contact->pair_penetrations(u_fe);
        for (unsigned int i = 0; i < per_pair.size(); ++i)
          out << "    pair " << i << " (surface body "
              << int(p.contact.pairs[i].surface_body) << " in volume body "
              << int(p.contact.pairs[i].volume_body)
              << "): largest penetration " << per_pair[i] << "\n";
      }
    if (contact && !p.contact.pairs.empty())
      out << "  contact tree: rebuilt " << contact->n_tree_rebuilds()
          << " times (a vertex moved more than the mean element size)\n";
    if (const auto *rigid = nonlinear_problem.free_rigid_bodies())
      for (unsigned int b = 0; b < rigid->n_bodies(); ++b)
        out << "  free rigid body '" << rigid->name(b) << "': center moved by "
            << rigid->translation(u, b) << ", rotated by "
            << rigid->rotation_vector(u, b).norm() * 180. / M_PI
            << " degrees\n";
    if (!final_results)
      final_results = std::make_unique<StepResults>(nonlinear_problem, u, 1.);
    final_results->print(out);
    out << "  statistics: " << results.statistics_file() << "\n";
    if (p.output.write_vtu)
      out << "  results: " << results.pvd_file() << " (open in ParaView)\n";
    if (p.output.print_timing)
      {
        // where the resident memory goes (base/memory_usage.h)
        const std::string memory = memory_summary();
        if (!memory.empty())
          out << "  " << memory << "\n";
      }
    times          = timer.get_summary_data(TimerOutput::total_wall_time);
    times["total"] = total.wall_time();
    return statistics;
  }
} // namespace TissueContact
