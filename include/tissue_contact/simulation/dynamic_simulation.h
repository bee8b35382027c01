#pragma once

#include <tissue_contact/dynamics/time_integrator.h>
#include <tissue_contact/simulation/checkpoint.h>
#include <tissue_contact/simulation/problem.h>

#include <fstream>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace TissueContact
{
  /**
   * The dynamic analysis the program runs when the prm says
   * "Time integration/Analysis = dynamic": the scene's static problem
   * (elasticity, loads, contact, prescribed motions) with the mass of its
   * bodies, integrated in time by Dynamics::TimeIntegrator
   * (doc/theory/06-dynamics.md). Writes a VTU per output interval, the PVD
   * series (time = simulated time) and a CSV line per step.
   */
  class DynamicSimulation
  {
  public:
    DynamicSimulation(const Scene::SceneParameters &parameters,
                      std::ostream                 &out);

    /** Integrate from rest at the reference configuration to the end
     * time; @p on_step, if given, sees every step taken. The time history
     * (<base>-time.csv) has per step: the kinetic energy, the total energy
     * (kinetic + elastic + contact - work of the loads), the energy the
     * damping dissipated so far (their sum stays constant up to the
     * scheme's error) and the penalty energy of each contact pair and
     * obstacle. Throws (one line) if a step fails below the minimum step or
     * the explicit scheme blows up; the output written so far is kept. */
    void
    run(const std::function<void(const Dynamics::TimeIntegrator &integrator,
                                 const Dynamics::State          &before,
                                 const Dynamics::State &after)> &on_step = {},
        const Checkpoint *restart = nullptr);

    /** The scene's problem it integrates (assembly, contact, energy). */
    const Problem &
    problem() const
    {
      return nonlinear_problem;
    }

    const Dynamics::State &
    state() const
    {
      return s;
    }

  private:
    /** run() with SUNDIALS' IDA (Scheme = IDA). */
    void
    run_ida();

    /** Create the output folder and <base>-time.csv with the header
     * @p columns; @p name gets its path. */
    std::ofstream
    open_time_history(const std::string &columns,
                      std::string       &name,
                      const bool         append = false) const;

    std::ostream        &out;
    Problem              nonlinear_problem;
    SparseMatrix<double> M;
    Vector<double>       M_lumped;
    Dynamics::State      s;
  };
} // namespace TissueContact
