#pragma once

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <limits>
#include <map>

namespace TissueContact
{
  namespace Solvers
  {
    using namespace dealii;

    /**
     * What the incremental Newton solver needs from a discrete problem
     * @f$R(u,\lambda) = 0@f$ with prescribed values on some DoFs:
     * residual and tangent, an admissibility check (no inverted element),
     * the prescribed values at a load factor, and the quasi-viscosity
     * diagonal. The solver knows nothing else about the physics.
     */
    class NonlinearProblem
    {
    public:
      virtual ~NonlinearProblem() = default;

      /** Number of unknowns. */
      virtual types::global_dof_index
      n_dofs() const = 0;

      /** Sparsity pattern of the tangent. */
      virtual const SparsityPattern &
      sparsity_pattern() const = 0;

      /**
       * Called before each assembly of the tangent at @p u: make
       * sparsity_pattern() hold every coupling that tangent will have (new
       * contact pairs couple nodes of different elements). Returns true if
       * the pattern changed; the solver then re-initializes its matrix.
       * With @p keep_couplings a new pattern may also keep the couplings
       * of the one it replaces that are no longer needed (their entries
       * stay zero), so that a pair that leaves and comes back calls for no
       * second build: a solver whose linear solves see only the nonzeros
       * passes it at every call of a load increment but the first. A call
       * without it makes the next build start anew, so the kept couplings
       * are those of one increment at most.
       */
      virtual bool
      update_sparsity_pattern(const Vector<double> &u,
                              const bool            keep_couplings = false)
      {
        (void)u;
        (void)keep_couplings;
        return false;
      }

      /** @f$R(u,\lambda)@f$ (all DoFs, prescribed ones included) and the
       * tangent when @p K is not null. Returns false if @p u is not
       * admissible (an inverted element); R and K are then unspecified. */
      virtual bool
      assemble(const Vector<double> &u,
               const double          load_factor,
               Vector<double>       &R,
               SparseMatrix<double> *K) = 0;

      /** The prescribed DoFs and their values at @p load_factor. */
      virtual std::map<types::global_dof_index, double>
      prescribed_values(const double load_factor) const = 0;

      /** Norm of the applied external forces at @p load_factor: with the
       * reactions, the force scale of the convergence test. */
      virtual double
      external_force_norm(const double load_factor) const = 0;

      /** Diagonal @f$D@f$ of the quasi-viscosity (dissertation 4.7.3)
       * for the dimensionless factor @p eta. */
      virtual Vector<double>
      quasi_viscosity_diagonal(const double eta) const = 0;

      /** The entries of sparsity_pattern() over those the element
       * couplings alone would have (>= 1; wider couplings raise it), for
       * the automatic choice of the linear solver
       * (LinearSolver::Parameters::resolved()); 1 (the default): no wider
       * couplings. */
      virtual double
      pattern_widening() const
      {
        return 1.;
      }

      /** A typical element size (length units), for the rounding floor
       * of the residual (doc/theory/04-solver.md sec. 4.2.1); 0 (the
       * default): none. */
      virtual double
      length_scale() const
      {
        return 0.;
      }

      /** The potential energy whose gradient assemble() computes, for the
       * energy line search; NaN (the default) if the problem has none. */
      virtual double
      energy(const Vector<double> &u, const double load_factor) const
      {
        (void)u;
        (void)load_factor;
        return std::numeric_limits<double>::quiet_NaN();
      }

      /**
       * The near-null space handed to the algebraic multigrid
       * preconditioner (LinearSolver with Type = GMRES+AMG, Trilinos ML's
       * pre-computed null space): the six rigid-body modes, three
       * translations and three rotations, as values at every unknown.
       * Empty (the default): AMG uses one constant mode over all DoFs.
       */
      virtual std::vector<Vector<double>>
      near_null_space() const
      {
        return {};
      }

      /**
       * An outer (augmented-Lagrangian) update after a converged solve at
       * @p u, the @p k-th of this load increment (k = 0, 1, ...): returns
       * true if the problem changed (its multipliers took a new value) and
       * the increment must be solved again. The default: no outer loop.
       */
      virtual bool
      update_multipliers(const Vector<double> &u, const unsigned int k)
      {
        (void)u;
        (void)k;
        return false;
      }

      /** The state update_multipliers() changes, to be restored when an
       * increment is cut back (empty: none). */
      virtual std::vector<double>
      multipliers() const
      {
        return {};
      }
      virtual void
      set_multipliers(const std::vector<double> &values)
      {
        (void)values;
      }
    };

    /**
     * A NonlinearProblem that forwards every call to another one: derive
     * from it and override what changes (the time integrators' effective
     * problem of one step, a test that watches the states a solver visits).
     */
    class ForwardingProblem : public NonlinearProblem
    {
    public:
      explicit ForwardingProblem(NonlinearProblem &inner)
        : inner(inner)
      {}

      types::global_dof_index
      n_dofs() const override
      {
        return inner.n_dofs();
      }
      const SparsityPattern &
      sparsity_pattern() const override
      {
        return inner.sparsity_pattern();
      }
      bool
      update_sparsity_pattern(const Vector<double> &u,
                              const bool keep_couplings = false) override
      {
        return inner.update_sparsity_pattern(u, keep_couplings);
      }
      bool
      assemble(const Vector<double> &u,
               const double          load_factor,
               Vector<double>       &R,
               SparseMatrix<double> *K) override
      {
        return inner.assemble(u, load_factor, R, K);
      }
      std::map<types::global_dof_index, double>
      prescribed_values(const double load_factor) const override
      {
        return inner.prescribed_values(load_factor);
      }
      double
      external_force_norm(const double load_factor) const override
      {
        return inner.external_force_norm(load_factor);
      }
      Vector<double>
      quasi_viscosity_diagonal(const double eta) const override
      {
        return inner.quasi_viscosity_diagonal(eta);
      }
      double
      length_scale() const override
      {
        return inner.length_scale();
      }
      double
      pattern_widening() const override
      {
        return inner.pattern_widening();
      }
      double
      energy(const Vector<double> &u, const double load_factor) const override
      {
        return inner.energy(u, load_factor);
      }
      std::vector<Vector<double>>
      near_null_space() const override
      {
        return inner.near_null_space();
      }
      bool
      update_multipliers(const Vector<double> &u, const unsigned int k) override
      {
        return inner.update_multipliers(u, k);
      }
      std::vector<double>
      multipliers() const override
      {
        return inner.multipliers();
      }
      void
      set_multipliers(const std::vector<double> &values) override
      {
        inner.set_multipliers(values);
      }

    protected:
      NonlinearProblem &inner;
    };
  } // namespace Solvers
} // namespace TissueContact
