#pragma once

#include <deal.II/lac/solver_control.h>

#include <cmath>

namespace TissueContact
{
  namespace Solvers
  {
    using namespace dealii;

    /**
     * A SolverControl for restarted GMRES that also gives up, as if at its
     * cap, when the residual cannot reach the tolerance at the rate of the
     * last restart cycle (doc/theory/04-solver.md sec. 4.5.1): at the end of
     * each cycle of @p restart iterations, with @f$r_c@f$ the residual then,
     * @f$r_{c-1}@f$ the one a cycle before (the start's, for the first) and
     * @f$m@f$ the cycles left before the cap,
     * @f[
     *   r_c \left(\frac{r_c}{r_{c-1}}\right)^{m} > \text{tolerance}
     *   \quad\Longrightarrow\quad \text{failure}.
     * @f]
     * A restarted GMRES that stagnates tends to go on stagnating (each
     * cycle starts a Krylov space of the same dimension from a residual
     * that has hardly changed), so a solve that would have run to its cap
     * anyway stops cycles early; one whose cycles keep their rate is not
     * touched, iteration for iteration. It is a prediction, not a proof: a
     * solve that would have found its rate again before the cap is stopped
     * too. It is meant where a failure has a remedy that does not use the
     * iterate (the automatic solver's direct fallback, which starts from
     * zero), so that stopping a solve that would have failed changes
     * nothing but the iterations spent, and stopping one that would have
     * converged late gives the exact step instead of an inexact one. With
     * @p restart = 0 it is a plain SolverControl.
     */
    class StagnationControl : public SolverControl
    {
    public:
      StagnationControl(const unsigned int max_steps,
                        const double       tolerance,
                        const unsigned int restart)
        : SolverControl(max_steps, tolerance, false, false)
        , restart(restart)
      {}

      State
      check(const unsigned int step, const double value) override
      {
        const State state = SolverControl::check(step, value);
        if (state != iterate || restart == 0)
          return state;
        if (step == 0)
          {
            cycle_start = value;
            next_end    = restart;
            return state;
          }
        // GMRES reports a cycle's last step twice (its estimate, then the
        // residual it restarts from): the first report decides
        if (step < next_end)
          return state;
        next_end += restart;
        const double rate = value / cycle_start;
        cycle_start       = value;
        const double cycles_left =
          double(max_steps() > step ? max_steps() - step : 0) / restart;
        if (!(rate < 1.) || value * std::pow(rate, cycles_left) > tolerance())
          {
            stagnated = true;
            return failure;
          }
        return state;
      }

      /** Whether the last solve stopped because it stagnated (not at its
       * cap, nor on a breakdown). */
      bool
      has_stagnated() const
      {
        return stagnated;
      }

    private:
      const unsigned int restart;
      double             cycle_start = 0.;
      unsigned int       next_end    = 0;
      bool               stagnated   = false;
    };
  } // namespace Solvers
} // namespace TissueContact
