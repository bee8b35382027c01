#pragma once

#include <tissue_contact/solvers/nonlinear_problem.h>

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

namespace TissueContact
{
  namespace Dynamics
  {
    using namespace dealii;

    /** K += c A entry by entry. A's pattern may hold couplings K's does
     * not (contact couplings of an earlier pattern): those are left out. */
    void
    add_scaled(SparseMatrix<double>       &K,
               const double                c,
               const SparseMatrix<double> &A);

    /**
     * The damping of the time integrators (doc/theory/06-dynamics.md,
     * sec. 1): @f$C = \alpha M + \beta K + D@f$ with the mass M (consistent
     * or lumped), K the problem's tangent at a chosen state (the initial
     * one, or the start of each step) and D the dissertation's nodal
     * viscosity, @f$D_a = \tau\sum_{e\ni a}\mu_eh_e/n_e@f$. One operator
     * for every scheme: applied to a vector (the damping force) and added
     * to an effective tangent.
     */
    class Damping
    {
    public:
      /** @p M or @p M_lumped (the consistent one is used if both). */
      Damping(const double                alpha,
              const double                beta,
              const double                tau,
              Solvers::NonlinearProblem  &problem,
              const SparseMatrix<double> *M,
              const Vector<double>       *M_lumped);

      /** Take K (if beta != 0) as the tangent at @p u, load factor
       * @p load_factor, and D (if tau > 0) from the problem. Throws if an
       * element is inverted at @p u. */
      void
      set_state(const Vector<double> &u, const double load_factor);

      /** @p Cx = C x */
      void
      vmult(Vector<double> &Cx, const Vector<double> &x) const;

      /** @p A += c C (A has the problem's current pattern). */
      void
      add_to(SparseMatrix<double> &A, const double c) const;

      const double alpha, beta, tau;

    private:
      Solvers::NonlinearProblem  &problem;
      const SparseMatrix<double> *M;
      const Vector<double>       *M_lumped;
      SparsityPattern             K_pattern;
      SparseMatrix<double>        K;
      Vector<double>              D;
    };
  } // namespace Dynamics
} // namespace TissueContact
