// Dissertation 6.5 reproduced: a wedge pushed into a notch
// (meshes/wedge_in_notch.geo, prm/wedge_in_notch.prm; the test's mesh is
// the coarse one, lc = 0.15). The wedge's material depth has a
// discontinuous gradient on its bisector, which the notch's apex crosses.
// For eps = 0, 10, 1e2, 1e3, 1e4 and both integration methods (area
// integration; point collocation at the triangle vertices):
//  - the largest penetration at the end (Table 1's trend), or the load
//    factor reached if the solve fails;
//  - the residual history over all Newton iterations (Figs. 31-35), written
//    to wedge_in_notch_histories.csv in the test's folder (columns: eps,
//    method, total iteration, increment, load factor, Newton iteration in
//    the increment, |R|; plotted by
//    contrib/plot_wedge_in_notch.sh) and summarized here: Newton iterations,
//    failed increments, and how often the residual grew.
// The dissertation runs it dynamically; here it is the static incremental
// solver (the wedge's right face moved by the load factor).

#include "../tests.h"

#include <tissue_contact/simulation/static_simulation.h>

#include <fstream>
#include <sstream>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

namespace
{
  std::string
  scene(const std::string &eps, const std::string &method)
  {
    std::ifstream in(std::string(SOURCE_DIR) + "/../../prm/wedge_in_notch.prm");
    std::ostringstream text;
    text << in.rdbuf();
    std::string s           = text.str();
    const auto  replace_all = [&](const std::string &from,
                                 const std::string &to) {
      for (std::size_t pos = s.find(from); pos != std::string::npos;
           pos             = s.find(from, pos + to.size()))
        s.replace(pos, from.size(), to);
    };
    replace_all("../meshes/wedge_in_notch.msh",
                std::string(SOURCE_DIR) + "/wedge_in_notch.msh");
    replace_all("Penalty factor = 1e3", "Penalty factor = " + eps);
    replace_all("Method         = area integration",
                "Method         = " + method);
    replace_all("set Base name = wedge_in_notch",
                "set Base name = wedge_in_notch\n  set Write VTU = false\n"
                "  set Print timing = false");
    return s;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  std::ofstream csv("wedge_in_notch_histories.csv");
  csv << "eps,method,iteration,increment,load_factor,newton_iteration,"
         "residual\n";
  for (const std::string eps : {"0", "10", "1e2", "1e3", "1e4"})
    for (const std::string method : {"area integration", "point collocation"})
      {
        if (eps == "0" && method == "point collocation")
          continue; // no contact force: the same run
        std::ostringstream log;
        StaticSimulation   sim(
          Scene::SceneParameters::from_string(scene(eps, method)), log);
        unsigned int total = 0, growths = 0;
        double       previous = -1., last_converged = 0.;
        std::string  outcome;
        try
          {
            const auto stats = sim.solve_quietly([&](const IterationInfo &i) {
              csv << eps << ',' << method << ',' << total++ << ','
                  << i.increment << ',' << i.load_factor << ',' << i.iteration
                  << ',' << i.residual_norm << '\n';
              if (i.iteration > 0 && i.residual_norm > previous)
                ++growths;
              if (i.step_length == 0.)
                last_converged = i.load_factor;
              previous = i.residual_norm;
            });
            std::ostringstream o;
            o << "converged, " << stats.increments << " increments, "
              << stats.cutbacks << " cut back";
            outcome = o.str();
          }
        catch (const std::exception &)
          {
            std::ostringstream o;
            o << "FAILED (load increment below the minimum; last converged "
                 "load factor "
              << last_converged << ")";
            outcome = o.str();
          }
        const double d =
          sim.problem().contact_assembler()->max_body_penetration(
            sim.solution());
        // a failing run's iteration counts depend on rounding (it
        // chatters until the increment is cut to the minimum): print a bound
        deallog << "eps " << std::setw(4) << eps << ", " << std::setw(17)
                << method << ": ";
        if (outcome.rfind("FAILED", 0) == 0)
          deallog << (total >= 200 ? "more than 200" : "fewer than 200")
                  << " Newton iterations, " << outcome << std::endl;
        else
          deallog << "max penetration " << std::setprecision(3) << d
                  << std::setprecision(6) << ", " << total
                  << " Newton iterations, residual grew in " << growths << ", "
                  << outcome << std::endl;
      }
}
