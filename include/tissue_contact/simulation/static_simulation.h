#pragma once

#include <tissue_contact/base/discretization.h>
#include <tissue_contact/contact/contact_assembler.h>
#include <tissue_contact/elasticity/elastic_assembler.h>
#include <tissue_contact/scene/scene.h>
#include <tissue_contact/solvers/newton_solver.h>

#include <deal.II/base/timer.h>

#include <memory>
#include <ostream>

namespace TissueContact
{
  using namespace dealii;

  /**
   * A static analysis of a scene, the program's main job: builds the mesh,
   * the finite element space and the assembler from the parameters, drives
   * the incremental Newton solver from load factor 0 to 1, and writes the
   * VTU/PVD series and the convergence log. It is the NonlinearProblem the
   * solver sees: residual and tangent of the elastic bodies, the prescribed
   * displacements of boundaries and rigid bodies at each load factor.
   */
  class StaticSimulation : public Solvers::NonlinearProblem
  {
  public:
    StaticSimulation(const Scene::SceneParameters &parameters,
                     std::ostream                 &out);

    /** Solve and write output. Throws (after keeping every result already
     * written) if the solve fails. */
    SolveStatistics
    run();

    /** Solve without writing any file (for tests); @p on_iteration, if
     * given, sees every Newton iteration. On failure the exception
     * propagates and solution() holds the last converged increment. */
    SolveStatistics
    solve_quietly(
      const std::function<void(const IterationInfo &)> &on_iteration = {});

    const Vector<double> &
    solution() const
    {
      return u;
    }
    const Discretization &
    discretization() const
    {
      return disc;
    }
    const Elasticity::ElasticAssembler &
    elastic_assembler() const
    {
      return assembler;
    }
    const Scene::Scene &
    get_scene() const
    {
      return scene;
    }
    /** The contact assembler, or null if the scene declares no contact. */
    const Contact::ContactAssembler *
    contact_assembler() const
    {
      return contact.get();
    }

    // NonlinearProblem
    types::global_dof_index
    n_dofs() const override
    {
      return disc.n_dofs();
    }
    /** The finite element pattern, plus the couplings of current contact
     * pairs. */
    const SparsityPattern &
    sparsity_pattern() const override
    {
      return sparsity;
    }
    bool
    update_sparsity_pattern(const Vector<double> &u) override;
    bool
    assemble(const Vector<double> &u,
             const double          load_factor,
             Vector<double>       &R,
             SparseMatrix<double> *K) override;
    std::map<types::global_dof_index, double>
    prescribed_values(const double load_factor) const override;
    double
    external_force_norm(const double load_factor) const override;
    Vector<double>
    quasi_viscosity_diagonal(const double eta) const override;
    std::vector<std::vector<bool>>
    constant_modes() const override;
    /** Elastic potential (with the loads' work) plus contact energy. */
    double
    energy(const Vector<double> &u, const double load_factor) const override;

    /** The same, and the contact energy per interaction in
     * @p contact_energies (ContactAssembler::energies(); empty without
     * contact). */
    double
    energy(const Vector<double> &u,
           const double          load_factor,
           std::vector<double>  &contact_energies) const;

  private:
    /** sparsity = the FE pattern + the contact couplings at @p u (with a
     * margin of half the smallest cell diameter, so that nearby pairs do
     * not force a rebuild at every iteration). */
    void
    rebuild_sparsity_pattern(const Vector<double> &u);

    Scene::Scene                               scene;
    Discretization                             disc;
    Elasticity::ElasticAssembler               assembler;
    std::unique_ptr<Contact::ContactAssembler> contact;
    /** The run's timer while run() is active: contact assembly is timed as
     * a part of the assembly. */
    TimerOutput                      *timer = nullptr;
    SparsityPattern                   sparsity;
    std::vector<Scene::PrescribedDof> prescribed;
    Vector<double>                    u;
    std::ostream                     &out;
  };
} // namespace TissueContact
