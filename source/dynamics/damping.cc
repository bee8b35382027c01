#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/dynamics/damping.h>

namespace TissueContact
{
  namespace Dynamics
  {
    void
    add_scaled(SparseMatrix<double>       &K,
               const double                c,
               const SparseMatrix<double> &A)
    {
      if (c == 0.)
        return;
      const bool same = &K.get_sparsity_pattern() == &A.get_sparsity_pattern();
      for (auto it = A.begin(); it != A.end(); ++it)
        if (it->value() != 0. &&
            (same || K.get_sparsity_pattern().exists(it->row(), it->column())))
          K.add(it->row(), it->column(), c * it->value());
    }


    Damping::Damping(const double                alpha,
                     const double                beta,
                     const double                tau,
                     Solvers::NonlinearProblem  &problem,
                     const SparseMatrix<double> *M,
                     const Vector<double>       *M_lumped)
      : alpha(alpha)
      , beta(beta)
      , tau(tau)
      , problem(problem)
      , M(M)
      , M_lumped(M_lumped)
    {
      AssertThrow(alpha == 0. || M != nullptr || M_lumped != nullptr,
                  ExcMessage("mass-proportional damping needs a mass matrix"));
    }


    void
    Damping::set_state(const Vector<double> &u, const double load_factor)
    {
      if (beta != 0.)
        {
          problem.update_sparsity_pattern(u);
          K.clear();
          K_pattern.copy_from(problem.sparsity_pattern());
          K.reinit(K_pattern);
          Vector<double> R(u.size());
          AssertThrow(problem.assemble(u, load_factor, R, &K),
                      ExcMessage("damping: an element is inverted in the "
                                 "state its stiffness is taken at"));
        }
      if (tau > 0. && D.size() == 0)
        D = problem.quasi_viscosity_diagonal(tau);
    }


    void
    Damping::vmult(Vector<double> &Cx, const Vector<double> &x) const
    {
      Cx.reinit(x.size());
      if (alpha != 0.)
        {
          if (M != nullptr)
            M->vmult(Cx, x);
          else
            for (types::global_dof_index i = 0; i < x.size(); ++i)
              Cx[i] = (*M_lumped)[i] * x[i];
          Cx *= alpha;
        }
      if (beta != 0.)
        {
          Vector<double> tmp(x.size());
          K.vmult(tmp, x);
          Cx.add(beta, tmp);
        }
      for (types::global_dof_index i = 0; i < D.size(); ++i)
        Cx[i] += D[i] * x[i];
    }


    void
    Damping::add_to(SparseMatrix<double> &A, const double c) const
    {
      if (alpha != 0.)
        {
          if (M != nullptr)
            add_scaled(A, c * alpha, *M);
          else
            for (types::global_dof_index i = 0; i < A.m(); ++i)
              A.add(i, i, c * alpha * (*M_lumped)[i]);
        }
      if (beta != 0.)
        add_scaled(A, c * beta, K);
      for (types::global_dof_index i = 0; i < D.size(); ++i)
        A.add(i, i, c * D[i]);
    }
  } // namespace Dynamics
} // namespace TissueContact
