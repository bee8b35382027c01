// Dynamic contact between deformable bodies: prm/falling_rods.prm
// (dissertation 8.2) on a 2 x 2 array (meshes/falling_rods_2x2.msh).
// Mooney-Rivlin rods clamped in a 45 degree foundation fall under gravity
// onto a rigid curved bar; the rods are one body, so rod-on-rod impacts
// are self-contact. Newmark with Rayleigh damping. Printed:
//  - when each contact interaction first carries energy (the bar is hit
//    from both sides: rod triangles in the bar and bar triangles in the
//    rods; rod on rod later);
//  - per rod the largest down-slope tip deflection and the one at the end,
//    against the linear cantilever's static deflection q L^4 / (8 E I);
//  - the largest penetration (material depth reached) over the run
//    against the rod radius;
//  - the energy balance E(t) + D(t) = E(0) = 0 (E: kinetic + elastic +
//    contact - work of gravity; D: dissipated by the damping), read from
//    the program's time history (Newmark conserves energy only for
//    linear problems: the penalty impacts, resolved by a few 0.01 steps,
//    lose some).

#include "../tests.h"
#include "scenes.h"

#include <tissue_contact/simulation/dynamic_simulation.h>

#include <fstream>
#include <map>
#include <sstream>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

namespace
{
  /** The columns of a CSV file, by header name. */
  std::map<std::string, std::vector<double>>
  read_csv(const std::string &name)
  {
    std::ifstream                              in(name);
    std::string                                line, cell;
    std::vector<std::string>                   header;
    std::map<std::string, std::vector<double>> columns;
    std::getline(in, line);
    for (std::istringstream h(line); std::getline(h, cell, ',');)
      header.push_back(cell);
    while (std::getline(in, line))
      {
        std::istringstream row(line);
        for (unsigned int c = 0; std::getline(row, cell, ','); ++c)
          columns[header.at(c)].push_back(std::stod(cell));
      }
    return columns;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const double      end_time = 1.;
  const std::string prm =
    project_prm("falling_rods.prm",
                {{"falling_rods.msh", "falling_rods_2x2.msh"},
                 {"set End time        = 4",
                  "set End time = " + std::to_string(end_time)}});
  std::ostringstream log;
  DynamicSimulation  sim(Scene::SceneParameters::from_string(prm), log);
  const auto        &problem = sim.problem();
  const DynamicsTestScenes::RodTips tips(problem.discretization());
  const unsigned int                n_rods = tips.centres.size();
  const double                      r      = tips.radius;

  std::vector<double> peak(n_rods, 0.);
  double              max_penetration = 0.;
  sim.run([&](const Dynamics::TimeIntegrator &,
              const Dynamics::State &,
              const Dynamics::State &after) {
    for (unsigned int k = 0; k < n_rods; ++k)
      peak[k] = std::max(peak[k], tips.deflection(after.u, k));
    max_penetration =
      std::max(max_penetration,
               problem.contact_assembler()->max_body_penetration(after.u));
  });

  const auto history = read_csv("falling_rods-time.csv");
  const auto first   = [&](const std::string &column) {
    const auto &W = history.at(column);
    for (unsigned int s = 0; s < W.size(); ++s)
      if (W[s] > 1e-12)
        return std::to_string(history.at("time")[s]).substr(0, 4);
    return std::string("never");
  };
  deallog << problem.n_dofs() << " unknowns, " << n_rods << " rods, t = 0.."
          << end_time << std::endl;
  deallog << "first contact energy: rods in the bar at t = "
          << first("contact_1_2") << ", bar in the rods "
          << first("contact_2_1") << ", rod on rod " << first("contact_1_1")
          << ", ground " << first("obstacle_0") << ", foundation "
          << first("obstacle_1") << std::endl;

  // E = 6 (C1 + C2) for small strains with lambda = 4 (C2 + a) = 2 mu:
  // E = mu (3 lambda + 2 mu) / (lambda + mu) = 8/3 mu
  const double mu = 1000., E = 8. / 3. * mu, A = numbers::PI * r * r,
               I = numbers::PI * std::pow(r, 4) / 4.,
               q = A * 10. * std::sqrt(0.5), L = tips.length;
  deallog << "down-slope tip deflection (linear static cantilever "
          << std::setprecision(3) << q * std::pow(L, 4) / (8. * E * I)
          << "):" << std::endl;
  for (unsigned int k = 0; k < n_rods; ++k)
    deallog << "  rod tip at (" << tips.centres[k][0] << ", "
            << tips.centres[k][1] << ", " << tips.centres[k][2] << "): largest "
            << peak[k] << ", at t = " << end_time << " "
            << tips.deflection(sim.state().u, k) << std::endl;
  deallog << "largest penetration / rod radius " << max_penetration / r
          << std::endl;

  const auto &energy     = history.at("energy"),
             &dissipated = history.at("dissipated");
  double balance         = 0.;
  for (unsigned int s = 0; s < energy.size(); ++s)
    balance = std::max(balance, std::abs(energy[s] + dissipated[s]));
  deallog << "energy balance: max |E + D| / D(end) " << std::setprecision(2)
          << balance / dissipated.back() << std::endl;
}
