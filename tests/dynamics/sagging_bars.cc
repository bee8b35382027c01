// The dynamic analysis settles at the static equilibrium: the three
// cantilevers of prm/sagging_bars.prm (paper Fig. 13; P2, neo-Hookean, three
// stiffnesses) released under gravity and damped by a drag, integrated to
// t = 4 by Newmark, against the static solve of the same scene. Printed
// per bar: the static tip deflection against Euler-Bernoulli
// (q L^4 / (8 E I)), and the dynamic one at t = 4 against the static.

#include "../tests.h"

#include <tissue_contact/simulation/dynamic_simulation.h>
#include <tissue_contact/simulation/static_simulation.h>

#include <sstream>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const std::string prm = project_prm("sagging_bars.prm");

  std::ostringstream log;
  DynamicSimulation  dynamic(Scene::SceneParameters::from_string(prm), log);
  dynamic.run();
  StaticSimulation stat(Scene::SceneParameters::from_string(
                          prm + "subsection Time integration\n  set Analysis "
                                "= static\nend\n"),
                        log);
  stat.solve_quietly();

  // tip deflection: the smallest z displacement of each bar's free end
  const auto &disc      = stat.problem().discretization();
  const auto  X         = disc.support_points();
  const auto  component = disc.dof_components();
  const auto  tip       = [&](const Vector<double> &u, const double y0) {
    double w = 0.;
    for (types::global_dof_index i = 0; i < u.size(); ++i)
      if (component[i] == 2 && X[i][0] > 1. - 1e-9 && X[i][1] >= y0 - 1e-9 &&
          X[i][1] <= y0 + 0.1 + 1e-9)
        w = std::min(w, u[i]);
    return w;
  };
  const double mu[3] = {1000., 3000., 10000.};
  for (unsigned int b = 0; b < 3; ++b)
    {
      const double E         = 2.5 * mu[b]; // lambda = mu: nu = 1/4
      const double EB        = 10. * 0.01 / (8. * E * 1e-4 / 12.);
      const double w_static  = tip(stat.solution(), 0.2 * b);
      const double w_dynamic = tip(dynamic.state().u, 0.2 * b);
      deallog << "bar " << b << " (mu " << int(mu[b]) << "): static tip "
              << std::setprecision(4) << -w_static << ", Euler-Bernoulli " << EB
              << "; dynamic at t = 4 / static " << w_dynamic / w_static
              << std::setprecision(6) << std::endl;
    }
}
