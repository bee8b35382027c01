#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/simulation/problem.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <numeric>

namespace TissueContact
{
  Problem::Problem(const Scene::SceneParameters &parameters)
    : scene(parameters)
    , disc(scene.triangulation, parameters.degree)
    , assembler(disc, scene.body_data(), scene.dead_loads())
    , prescribed(scene.prescribed_dofs(disc))
  {
    // contact only where the scene asks for it: no obstacle and no pair,
    // no contact search
    if (parameters.contact.enabled())
      contact =
        std::make_unique<Contact::ContactAssembler>(disc, parameters.contact);
    rebuild_sparsity_pattern(Vector<double>(disc.n_dofs()));
  }


  const std::vector<double> *
  Problem::depth_field() const
  {
    return contact && !scene.parameters.contact.pairs.empty() ?
             &contact->vertex_depth() :
             nullptr;
  }


  void
  Problem::rebuild_sparsity_pattern(const Vector<double> &u)
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
  Problem::update_sparsity_pattern(const Vector<double> &u)
  {
    if (!contact || scene.parameters.contact.pairs.empty() ||
        contact->has_couplings(u, sparsity))
      return false;
    rebuild_sparsity_pattern(u);
    return true;
  }


  bool
  Problem::assemble(const Vector<double> &u,
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
  Problem::energy(const Vector<double> &u, const double load_factor) const
  {
    const double W = assembler.energy(u, load_factor);
    return contact ? W + contact->energy(u) : W;
  }


  double
  Problem::energy(const Vector<double> &u,
                  const double          load_factor,
                  std::vector<double>  &contact_energies) const
  {
    contact_energies = contact ? contact->energies(u) : std::vector<double>();
    return std::accumulate(contact_energies.begin(),
                           contact_energies.end(),
                           assembler.energy(u, load_factor));
  }


  std::map<types::global_dof_index, double>
  Problem::prescribed_values(const double load_factor) const
  {
    std::map<types::global_dof_index, double> values;
    for (const auto &p : prescribed)
      values[p.dof] = p.motion->displacement(p.X, load_factor)[p.component];
    return values;
  }


  double
  Problem::external_force_norm(const double load_factor) const
  {
    return load_factor * assembler.external_force().l2_norm();
  }


  Vector<double>
  Problem::quasi_viscosity_diagonal(const double eta) const
  {
    return assembler.quasi_viscosity_diagonal(eta);
  }


  std::vector<std::vector<bool>>
  Problem::constant_modes() const
  {
    std::vector<std::vector<bool>> modes;
    DoFTools::extract_constant_modes(disc.dof_handler,
                                     ComponentMask(3, true),
                                     modes);
    return modes;
  }
} // namespace TissueContact
