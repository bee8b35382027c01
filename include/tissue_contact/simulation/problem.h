#pragma once

#include <tissue_contact/base/discretization.h>
#include <tissue_contact/contact/contact_assembler.h>
#include <tissue_contact/elasticity/elastic_assembler.h>
#include <tissue_contact/rigid/free_rigid_bodies.h>
#include <tissue_contact/scene/scene.h>
#include <tissue_contact/solvers/nonlinear_problem.h>

#include <deal.II/base/timer.h>

#include <memory>
#include <vector>

namespace TissueContact
{
  using namespace dealii;

  /**
   * What a scene is, as the discrete problem the solvers see: the mesh and
   * its bodies (Scene::Scene), the finite element space, the elastic weak
   * form with its dead loads (Elasticity::ElasticAssembler), the contact
   * interactions the scene declares (none: no contact search at all) and the
   * prescribed displacements of boundaries and rigid bodies, and the free
   * rigid bodies (Rigid::FreeRigidBodies: six unknowns each, after the
   * finite element DoFs, their nodes' DoFs slaved to them). As a
   * Solvers::NonlinearProblem it gives the residual and tangent
   * @f$R(u,\lambda) = f_{int}(u) + \partial W_c/\partial u - \lambda
   * f_{ext}@f$, the potential energy and the prescribed values at a load
   * factor (doc/theory/02, 04, 05). The drivers own one:
   * StaticSimulation (load stepping) and DynamicSimulation (time
   * integration, which adds the mass).
   */
  class Problem : public Solvers::NonlinearProblem
  {
  public:
    /** Build the scene of @p parameters (mesh checked, materials
     * created), its finite element space and assemblers. Throws naming
     * what is wrong in the input. */
    explicit Problem(const Scene::SceneParameters &parameters);

    const Scene::Scene &
    get_scene() const
    {
      return scene;
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
    /** The contact assembler, or null if the scene declares no contact. */
    const Contact::ContactAssembler *
    contact_assembler() const
    {
      return contact.get();
    }
    /** The material depth at every vertex for the output, or null if the
     * scene declares no body pair. */
    const std::vector<double> *
    depth_field() const;
    /** The free rigid bodies, or null if the scene has none. */
    const Rigid::FreeRigidBodies *
    free_rigid_bodies() const
    {
      return rigid.get();
    }
    /** The displacement of every finite element DoF (disc.n_dofs()
     * entries) in the unknowns @p u (n_dofs()): @p u itself without free
     * rigid bodies, else with their nodes' DoFs set by their motion. What
     * output and post-processing read. */
    Vector<double>
    displacement(const Vector<double> &u) const;
    /** Set the free rigid bodies' slave entries of @p u to their motion
     * (nothing without free rigid bodies). */
    void
    complete(Vector<double> &u) const
    {
      if (rigid)
        rigid->complete(u);
    }
    /** The largest penetration of a contact vertex into a paired body
     * (Contact::ContactAssembler::body_penetrations()) divided by the
     * local element size there, the smallest diameter of the cells around
     * the vertex; 0 without body pairs. */
    double
    max_relative_penetration(const Vector<double> &u) const;
    /**
     * The support reaction of one group of prescribed DoFs (a Dirichlet
     * condition, or a body with a prescribed rigid motion): the force
     * @f$F = \sum_i R_i e_{c_i}@f$ the support exerts on the body, R the
     * residual @f$f_{int} + \partial W_c/\partial u - \lambda f_{ext}@f$
     * at the group's DoFs (at equilibrium it balances the rest), and its
     * moment @f$M = \sum_i (x_i - c) \times R_i e_{c_i}@f$ about the
     * group's current centroid c (doc/theory/02-weak-form-and-linearization.md,
     * sec. 2.5).
     */
    struct Reaction
    {
      std::string  name;
      Tensor<1, 3> force, moment;
      Point<3>     centroid;
    };
    /** The reaction of every Dirichlet condition (in the declared order,
     * named "dirichlet<i>_boundary<id>"), then of every body with a
     * prescribed rigid motion ("body_<name>"), at the state @p u and load
     * factor @p load_factor. A DoF in two conditions counts for the first. */
    std::vector<Reaction>
    reactions(const Vector<double> &u, const double load_factor) const;
    /** The strain energy of @p u (no load's work). */
    double
    strain_energy(const Vector<double> &u) const
    {
      return assembler.energy(fe_displacement(u), 0.);
    }
    /** What the scene asks for that is legal but likely unintended, one
     * line each (a contact pair or obstacle with penalty 0); the drivers
     * print them as warnings. */
    std::vector<std::string>
    warnings() const;
    /** Number of prescribed DoFs. */
    std::size_t
    n_prescribed() const
    {
      return prescribed.size();
    }
    /** While set, contact assembly is timed as the section "assembly:
     * contact part" of @p timer, and its search, energies, sparsity check
     * and insertion as "contact: ..." (null: not timed). */
    void
    set_timer(TimerOutput *timer)
    {
      this->timer = timer;
      if (contact)
        contact->set_timer(timer);
    }

    // NonlinearProblem
    types::global_dof_index
    n_dofs() const override
    {
      return rigid ? rigid->n_dofs() : disc.n_dofs();
    }
    /** The finite element pattern, plus the couplings of current contact
     * pairs. */
    const SparsityPattern &
    sparsity_pattern() const override
    {
      return sparsity;
    }
    bool
    update_sparsity_pattern(const Vector<double> &u,
                            const bool keep_couplings = false) override;
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
    /** The mean size of the deformable elements
     * (ElasticAssembler::mean_element_size()). */
    double
    length_scale() const override
    {
      return assembler.mean_element_size();
    }
    /** The tangent's entries (the vertex volume term's couplings, the
     * contact pairs' of the current state, the free rigid bodies') over the
     * discretization's. */
    double
    pattern_widening() const override
    {
      return double(sparsity_pattern().n_nonzero_elements()) /
             disc.sparsity_pattern.n_nonzero_elements();
    }
    /** The six rigid-body modes (Discretization::rigid_body_modes()),
     * zero on the free rigid bodies' slaves and, on their unknowns, the
     * same motion: the centre's translation and the rotation vector.
     * AMG's near-null space. */
    std::vector<Vector<double>>
    near_null_space() const override;
    /** The augmented-Lagrangian update of the obstacles' multipliers
     * (ObstacleAssembler::update_multipliers(), Contact/Augmented
     * Lagrangian): true if the contact was violated by more than the
     * Penetration tolerance and @p k < Maximum multiplier updates. Records
     * the increments that ended above the tolerance
     * (multiplier_warnings()). */
    bool
    update_multipliers(const Vector<double> &u, const unsigned int k) override;
    std::vector<double>
    multipliers() const override;
    void
    set_multipliers(const std::vector<double> &values) override;
    /** Load steps whose contact violation stayed above the
     * augmented-Lagrangian tolerance after Maximum multiplier updates, with
     * it. */
    const std::vector<std::string> &
    multiplier_warnings() const
    {
      return multiplier_warning_lines;
    }

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
     * not force a rebuild at every iteration); with @p keep_couplings
     * the current pattern's couplings stay in it too, and only those near
     * the ones the sparsity check found missing are searched for. */
    void
                 rebuild_sparsity_pattern(const Vector<double> &u,
                                          const bool            keep_couplings = false);
    unsigned int n_pattern_builds = 0;
    /** The next build starts from the finite element pattern even if it
     * is asked to keep the couplings: a call without keep_couplings has
     * come since the last build (a new load increment). */
    bool                     next_build_fresh = true;
    std::vector<std::string> multiplier_warning_lines;

  public:
    /** How often the sparsity pattern was built (once at the start, again
     * when an active contact pair lacked its couplings). */
    unsigned int
    n_sparsity_patterns() const
    {
      return n_pattern_builds;
    }

  private:
    Scene::Scene                               scene;
    Discretization                             disc;
    Elasticity::ElasticAssembler               assembler;
    std::unique_ptr<Contact::ContactAssembler> contact;
    std::unique_ptr<Rigid::FreeRigidBodies>    rigid;
    /** @p u itself without free rigid bodies; else u_fe set to
     * displacement(@p u), without a copy of @p u where there is nothing
     * to complete (the assembly's path). */
    const Vector<double> &
    fe_displacement(const Vector<double> &u) const;

    /** With free rigid bodies: the finite element displacement and residual
     * (disc.n_dofs()) of the last assemble() or energy(). */
    mutable Vector<double>            u_fe, R_fe;
    TimerOutput                      *timer = nullptr;
    SparsityPattern                   sparsity;
    std::vector<Scene::PrescribedDof> prescribed;
    /** The contact pattern's search margin: half the smallest cell
     * diameter of the (fixed) reference mesh, found once. */
    double coupling_margin = 0.;
  };
} // namespace TissueContact
