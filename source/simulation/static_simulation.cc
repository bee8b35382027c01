#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/output/convergence_log.h>
#include <tissue_contact/output/vtu_writer.h>
#include <tissue_contact/simulation/static_simulation.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <filesystem>
#include <numeric>

namespace TissueContact
{
  StaticSimulation::StaticSimulation(const Scene::SceneParameters &parameters,
                                     std::ostream                 &out)
    : scene(parameters)
    , disc(scene.triangulation, parameters.degree)
    , assembler(disc, scene.body_data(), scene.dead_loads())
    , prescribed(scene.prescribed_dofs(disc))
    , u(disc.n_dofs())
    , out(out)
  {
    // contact only where the scene asks for it: no obstacle and no pair,
    // no contact search
    if (parameters.contact.enabled())
      contact =
        std::make_unique<Contact::ContactAssembler>(disc, parameters.contact);
    rebuild_sparsity_pattern(u);
  }


  void
  StaticSimulation::rebuild_sparsity_pattern(const Vector<double> &u)
  {
    if (!contact || scene.parameters.contact.pairs.empty())
      {
        sparsity.copy_from(disc.sparsity_pattern);
        return;
      }
    DynamicSparsityPattern dsp(disc.n_dofs());
    DoFTools::make_sparsity_pattern(disc.dof_handler, dsp);
    contact->add_couplings(
      u, 0.5 * GridTools::minimal_cell_diameter(scene.triangulation), dsp);
    sparsity.copy_from(dsp);
  }


  bool
  StaticSimulation::update_sparsity_pattern(const Vector<double> &u)
  {
    if (!contact || scene.parameters.contact.pairs.empty() ||
        contact->has_couplings(u, sparsity))
      return false;
    rebuild_sparsity_pattern(u);
    return true;
  }


  bool
  StaticSimulation::assemble(const Vector<double> &u,
                             const double          load_factor,
                             Vector<double>       &R,
                             SparseMatrix<double> *K)
  {
    if (!assembler.assemble(u, load_factor, R, K))
      return false;
    if (contact)
      {
        std::unique_ptr<TimerOutput::Scope> scope;
        if (timer != nullptr)
          scope =
            std::make_unique<TimerOutput::Scope>(*timer,
                                                 "assembly: contact part");
        contact->assemble(u, R, K);
      }
    return true;
  }


  double
  StaticSimulation::energy(const Vector<double> &u,
                           const double          load_factor) const
  {
    const double W = assembler.energy(u, load_factor);
    return contact ? W + contact->energy(u) : W;
  }


  double
  StaticSimulation::energy(const Vector<double> &u,
                           const double          load_factor,
                           std::vector<double>  &contact_energies) const
  {
    contact_energies = contact ? contact->energies(u) : std::vector<double>();
    return std::accumulate(contact_energies.begin(),
                           contact_energies.end(),
                           assembler.energy(u, load_factor));
  }


  std::map<types::global_dof_index, double>
  StaticSimulation::prescribed_values(const double load_factor) const
  {
    std::map<types::global_dof_index, double> values;
    for (const auto &p : prescribed)
      values[p.dof] = p.motion->displacement(p.X, load_factor)[p.component];
    return values;
  }


  double
  StaticSimulation::external_force_norm(const double load_factor) const
  {
    return load_factor * assembler.external_force().l2_norm();
  }


  Vector<double>
  StaticSimulation::quasi_viscosity_diagonal(const double eta) const
  {
    return assembler.quasi_viscosity_diagonal(eta);
  }


  std::vector<std::vector<bool>>
  StaticSimulation::constant_modes() const
  {
    std::vector<std::vector<bool>> modes;
    DoFTools::extract_constant_modes(disc.dof_handler,
                                     ComponentMask(3, true),
                                     modes);
    return modes;
  }


  SolveStatistics
  StaticSimulation::solve_quietly(
    const std::function<void(const IterationInfo &)> &on_iteration)
  {
    Solvers::IncrementalNewtonSolver solver(scene.parameters.solver);
    solver.on_iteration = on_iteration;
    u                   = 0.;
    return solver.solve(*this, u);
  }


  SolveStatistics
  StaticSimulation::run()
  {
    const auto &p = scene.parameters;
    TimerOutput timer(out,
                      p.output.print_timing ? TimerOutput::summary :
                                              TimerOutput::never,
                      TimerOutput::wall_times);

    out << "TissueContact static analysis\n"
        << "  mesh: " << scene.triangulation.n_active_cells() << " tetrahedra, "
        << scene.triangulation.n_vertices() << " vertices; P" << p.degree
        << " elements, " << disc.n_dofs() << " unknowns, " << prescribed.size()
        << " prescribed\n";
    for (const auto &b : p.bodies)
      out << "  body '" << b.name << "' (material id " << int(b.id)
          << "): " << b.material.model << (b.material.fiber ? " + fibers" : "")
          << "\n";
    out << "  linear solver: " << p.solver.linear_solver.type << "\n";
    if (contact)
      out << "  contact: " << contact->n_triangles() << " contact triangles, "
          << p.contact.obstacles.size() << " obstacle(s), "
          << p.contact.pairs.size() << " body pair(s)\n";

    std::filesystem::create_directories(p.output.directory);
    const std::string csv =
      p.output.directory + "/" + p.output.base_name + "-convergence.csv";
    Output::ConvergenceLog  log(out, csv);
    Output::VtuSeriesWriter vtu(p.output.directory, p.output.base_name);

    // the material depth is written when body contact is declared
    const auto depth_field = [&]() -> const std::vector<double> * {
      return contact && !p.contact.pairs.empty() ? &contact->vertex_depth() :
                                                   nullptr;
    };

    Solvers::IncrementalNewtonSolver solver(p.solver);
    solver.on_iteration = [&](const IterationInfo &i) { log.iteration(i); };
    solver.on_cutback   = [&](const double lambda, const std::string &why) {
      log.cutback(lambda, why);
    };
    solver.on_increment =
      [&](const unsigned int, const double lambda, const Vector<double> &u) {
        if (p.output.write_vtu)
          {
            TimerOutput::Scope scope(timer, "output");
            vtu.write(disc, assembler, u, lambda, depth_field());
          }
      };

    u = 0.;
    if (p.output.write_vtu)
      vtu.write(disc, assembler, u, 0., depth_field());

    SolveStatistics statistics;
    try
      {
        this->timer = &timer;
        statistics  = solver.solve(*this, u, &timer);
        this->timer = nullptr;
      }
    catch (const std::exception &e)
      {
        this->timer = nullptr;
        const std::string kept =
          p.output.write_vtu ?
            "; the converged increments are kept in " + vtu.pvd_file() :
            "";
        AssertThrow(false, ExcMessage(error_message(e) + kept));
      }

    double u_max = 0.;
    for (const double v : u)
      u_max = std::max(u_max, std::abs(v));
    out << "Converged: " << statistics.increments << " increments ("
        << statistics.cutbacks << " cut back), " << statistics.newton_iterations
        << " Newton iterations, " << statistics.linear_iterations
        << " linear iterations\n"
        << "  max |u_i| = " << u_max
        << ", min J = " << assembler.min_jacobian(u) << "\n"
        << "  convergence log: " << csv << "\n";
    if (contact && !p.contact.obstacles.empty())
      out << "  obstacle force on the bodies " << contact->obstacle_force(u)
          << ", max penetration " << contact->max_obstacle_penetration(u)
          << "\n";
    if (contact && !p.contact.pairs.empty())
      out << "  penetration (largest material depth reached by a contact "
             "vertex inside a paired body): "
          << contact->max_body_penetration(u) << "\n"
          << "  contact tree: rebuilt " << contact->n_tree_rebuilds()
          << " times (a vertex moved more than the mean element size)\n";
    if (p.output.write_vtu)
      out << "  results: " << vtu.pvd_file() << " (open in ParaView)\n";
    return statistics;
  }
} // namespace TissueContact
