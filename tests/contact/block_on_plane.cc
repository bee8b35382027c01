// A block pressed onto a rigid obstacle by a traction p on its top face
// (frictionless; symmetry conditions x = 0 on x-, y = 0 on y-; the body
// starts touching the obstacle, so the first step is regularized by the
// quasi-viscosity). For penalty factors eps = 1e2 ... 1e5: the reaction of
// the obstacle equals the applied load, and the penetration falls as 1/eps
// (for a uniform pressure, p = eps d). Also a large sphere as the obstacle,
// and Newton's convergence with contact in the last increment (the ratios
// r_k+1 / r_k^2 stay bounded: quadratic once the contact set has settled).

#include "../tests.h"

#include <tissue_contact/simulation/static_simulation.h>

#include <sstream>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

namespace
{
  std::string
  scene(const std::string &obstacle)
  {
    return R"(
subsection Mesh
  set Box upper corner = 1, 1, 0.5
  set Box subdivisions = 4, 4, 2
end
subsection Bodies
  subsection Body 0
    set Model  = neo-Hookean
    set Mu     = 100
    set Lambda = 100
  end
end
subsection Boundary conditions
  set Number of Dirichlet conditions = 2
  set Number of tractions = 1
  subsection Dirichlet 0
    set Boundary id = 0
    set Components  = x
  end
  subsection Dirichlet 1
    set Boundary id = 2
    set Components  = y
  end
  subsection Traction 0
    set Boundary id = 5
    set Traction    = 0, 0, -10
  end
end
subsection Contact
  set Contact surfaces    = 4
  set Number of obstacles = 1
  subsection Obstacle 0
)" + obstacle +
           R"(
  end
end
subsection Newton
  set Quasi-viscosity = true
  set Maximum line search halvings = 25
end
subsection Output
  set Write VTU    = false
  set Print timing = false
  set Directory    = .
end
)";
  }

  // residuals of the last increment, from the screen log
  std::vector<double>
  last_increment_residuals(const std::string &log)
  {
    std::vector<double> r;
    std::istringstream  in(log);
    std::string         line;
    while (std::getline(in, line))
      {
        if (line.rfind("Increment", 0) == 0)
          r.clear();
        std::istringstream l(line);
        unsigned int       it;
        double             res;
        if (line.size() > 2 && line[0] == ' ' && (l >> it >> res))
          r.push_back(res);
      }
    return r;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const double load = 10.;
  for (const std::string eps : {"1e2", "1e3", "1e4", "1e5"})
    {
      std::ostringstream log;
      StaticSimulation   sim(Scene::SceneParameters::from_string(scene(
                             "    set Type = plane\n    set Penalty factor = " +
                             eps)),
                           log);
      const auto         stats = sim.run();
      const auto        *c     = sim.problem().contact_assembler();
      const Tensor<1, 3> F     = c->obstacle_force(sim.solution());
      const double       d     = c->max_obstacle_penetration(sim.solution());
      deallog << "plane, eps = " << eps << ": reaction / load - 1 "
              << error_bound(std::abs(F[2] / load - 1.), -8)
              << ", tangential reaction "
              << error_bound(std::hypot(F[0], F[1]), -10)
              << ", max penetration " << std::setprecision(3) << d
              << ", eps * penetration / p " << std::stod(eps) * d / load
              << std::setprecision(6) << ", Newton iterations "
              << stats.newton_iterations << std::endl;
      if (eps == "1e3")
        {
          const auto r = last_increment_residuals(log.str());
          deallog << "  last increment, residuals:";
          for (const double v : r)
            deallog << " " << scientific(v);
          deallog << std::defaultfloat << std::setprecision(6) << std::endl;
          // bounded for quadratic convergence
          deallog << "  r_k+1 / r_k^2:";
          for (unsigned int k = 0; k + 1 < r.size(); ++k)
            deallog << " " << scientific(r[k + 1] / (r[k] * r[k]));
          deallog << std::defaultfloat << std::setprecision(6) << std::endl;
        }
    }

  // a sphere of radius 10 touching the bottom face at its center
  std::ostringstream log;
  StaticSimulation   sim(Scene::SceneParameters::from_string(scene(
                         "    set Type = sphere\n    set Center = 0, 0, -10\n"
                           "    set Radius = 10\n    set Penalty factor = 1e3")),
                       log);
  sim.run();
  const Tensor<1, 3> F =
    sim.problem().contact_assembler()->obstacle_force(sim.solution());
  deallog << "sphere R = 10, eps = 1e3: vertical reaction / load - 1 "
          << error_bound(std::abs(F[2] / load - 1.), -8) << ", max penetration "
          << std::setprecision(3)
          << sim.problem().contact_assembler()->max_obstacle_penetration(
               sim.solution())
          << std::setprecision(6) << std::endl;
}
