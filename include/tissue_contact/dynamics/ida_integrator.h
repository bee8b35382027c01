#pragma once

#include <tissue_contact/dynamics/time_integrator.h>
#include <tissue_contact/solvers/nonlinear_problem.h>

#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/sundials/ida.h>

#include <functional>

namespace TissueContact
{
  namespace Dynamics
  {
    using namespace dealii;

    /**
     * SUNDIALS' IDA (variable order, variable step BDF with error
     * control) as the alternative time integrator
     * (doc/theory/06-dynamics.md, sec. 6): the first-order system for
     * @f$y = (u, v)@f$,
     * @f[ F(t, y, \dot y) = \begin{pmatrix} \dot u - v \\
     *     M\dot v + C v + R(u) \end{pmatrix} = 0, @f]
     * with the prescribed DoFs as algebraic equations
     * @f$u_i = \bar u_i(t)@f$, @f$v_i = \dot{\bar u}_i(t)@f$. The
     * Jacobian @f$\partial F/\partial y + \alpha\,\partial F/\partial\dot
     * y@f$ is solved by eliminating the velocity:
     * @f$(K + \alpha^2 M + \alpha C)\,\delta u = r_v + (\alpha M + C)\,r_u@f$,
     * @f$\delta v = \alpha\,\delta u - r_u@f$, with the project's tangent
     * (a sparse LU per Jacobian setup).
     */
    class IdaIntegrator
    {
    public:
      /** @p data: IDA's settings (its final time is the end time);
       * damping and ramp time from @p parameters. */
      IdaIntegrator(const SUNDIALS::IDA<Vector<double>>::AdditionalData &data,
                    const TimeIntegrator::Parameters &parameters,
                    Solvers::NonlinearProblem        &problem,
                    const SparseMatrix<double>       &mass);

      /** Integrate from @p s (its t, u, v) to the final time; @p output is
       * called at every output time of IDA's AdditionalData. On return
       * @p s holds the final state. Returns the number of time steps. */
      unsigned int
      integrate(State &s, const std::function<void(const State &)> &output);

      /** Number of Jacobian setups of the last integrate(). */
      unsigned int n_jacobian_setups = 0;

    private:
      const SUNDIALS::IDA<Vector<double>>::AdditionalData data;
      const TimeIntegrator::Parameters                    parameters;
      Solvers::NonlinearProblem                          &problem;
      const SparseMatrix<double>                         &M;
    };
  } // namespace Dynamics
} // namespace TissueContact
