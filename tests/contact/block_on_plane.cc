// A block pressed onto a rigid obstacle by a traction p on its top face
// (frictionless; symmetry conditions x = 0 on x-, y = 0 on y-; the body
// starts touching the obstacle, so the first step is regularized by the
// quasi-viscosity). For penalty factors eps = 1e2 ... 1e5: the reaction of
// the obstacle equals the applied load, and the penetration falls as 1/eps
// (for a uniform pressure, p = eps d). Also a large sphere as the obstacle,
// and Newton's convergence with contact in the last increment (the ratios
// r_k+1 / r_k^2 stay bounded: quadratic once the contact set has settled).
// The run's results (StepResults, the statistics file): the contact traction
// integrated over the contact surface equals the load, the normal pressure
// integrated nearly (the bottom's normals tilt where it bulges), the contact
// area is the bottom face, widened by the bulge; with the block pressed down
// by its clamped top face instead, the top's vertical reaction is minus the
// contact force, the horizontal reactions balance, and the last row of
// <base>-statistics.csv holds the same numbers. Under the sphere, the pressure
// field of the output: its area, center, largest and far-corner values.
// Finally the augmented-Lagrangian loop at a penalty 100 times below the
// default: the bottom stays on the plane within 1e-6 of the height.

#include "../tests.h"

#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/simulation/static_simulation.h>
#include <tissue_contact/simulation/step_results.h>

#include <fstream>
#include <map>
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

  // run @p sim; for the plain penalty (not @p augmented) log how it ends
  // instead (it cannot hold the block at this penalty)
  bool
  solve_or_log_static(StaticSimulation &sim,
                      SolveStatistics  &stats,
                      const bool        augmented)
  {
    try
      {
        stats = sim.run();
        if (!augmented)
          deallog
            << "eps = 10, plain penalty: converged, max penetration "
            << std::setprecision(3)
            << sim.problem().contact_assembler()->max_obstacle_penetration(
                 sim.solution())
            << std::setprecision(6) << std::endl;
        return augmented;
      }
    catch (const std::exception &e)
      {
        deallog << "eps = 10, "
                << (augmented ? "augmented Lagrangian" : "plain penalty")
                << ": stops (" << std::string(error_message(e)).substr(0, 60)
                << "...)" << std::endl;
        return false;
      }
  }

  // sum_a t_a A_a (the traction integrated) and sum_a p_a A_a (the normal
  // pressure integrated) over the vertices
  void
  print_integrated_pressure(const StepResults &r, const double load)
  {
    const auto  &c = r.contact;
    double       P = 0.;
    Tensor<1, 3> T;
    for (unsigned int v = 0; v < c.area.size(); ++v)
      {
        P += c.pressure[v] * c.area[v];
        T += c.traction[v] * c.area[v];
      }
    const auto &obstacle = c.interactions[0];
    deallog << "  integrated contact traction z / load - 1 "
            << error_bound(std::abs(T[2] / load - 1.), -8)
            << ", integrated traction - contact force "
            << error_bound((T - obstacle.force).norm() / load, -12)
            << ", integrated normal pressure / load - 1 "
            << std::setprecision(2) << P / load - 1. << std::setprecision(6)
            << ", contact area " << obstacle.area << ", largest penetration "
            << std::setprecision(3) << obstacle.max_penetration
            << std::setprecision(6) << std::endl;
  }

  // the last row of a CSV file, by column name
  std::map<std::string, double>
  last_row(const std::string &file)
  {
    std::ifstream in(file);
    std::string   header, line, last, cell;
    std::getline(in, header);
    while (std::getline(in, line))
      last = line;
    std::istringstream            h(header), l(last);
    std::map<std::string, double> row;
    while (std::getline(h, cell, ','))
      {
        std::string value;
        std::getline(l, value, ',');
        row[cell] = std::stod(value);
      }
    return row;
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
          print_integrated_pressure(
            StepResults(sim.problem(), sim.solution(), 1.), load);
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
  {
    // the pressure field under the sphere (the output's contact_pressure):
    // highest at the center (the corner x = y = 0 of this symmetric
    // quarter), falling outwards; against the mean pressure load / area
    const StepResults r(sim.problem(), sim.solution(), 1.);
    const auto &X     = sim.problem().get_scene().triangulation.get_vertices();
    double      p_max = 0., p_center = 0., p_edge = 0.;
    for (unsigned int v = 0; v < X.size(); ++v)
      if (r.contact.area[v] > 0.)
        {
          p_max = std::max(p_max, r.contact.pressure[v]);
          if (X[v].norm() < 1e-12)
            p_center = r.contact.pressure[v];
          if (std::abs(X[v][0] - 1.) < 1e-12 && std::abs(X[v][1] - 1.) < 1e-12)
            p_edge = r.contact.pressure[v];
        }
    const double area = r.contact.interactions[0].area;
    deallog << "  pressure field: contact area " << std::setprecision(3) << area
            << ", mean pressure load / area " << load / area
            << ", at the center " << p_center << ", largest " << p_max
            << ", at the far corner " << p_edge << std::setprecision(6)
            << std::endl;
  }

  // pressed by its clamped top face, 0.02 down, instead of a traction
  {
    std::string text =
      scene("    set Type = plane\n    set Penalty factor = 1e3");
    const std::string traction = "  set Number of tractions = 1\n";
    text.replace(text.find(traction), traction.size(), "");
    text.replace(text.find("  subsection Traction 0"),
                 std::string(
                   "  subsection Traction 0\n    set Boundary id = 5\n"
                   "    set Traction    = 0, 0, -10\n  end\n")
                   .size(),
                 "");
    text.replace(text.find("Number of Dirichlet conditions = 2"),
                 std::string("Number of Dirichlet conditions = 2").size(),
                 "Number of Dirichlet conditions = 3\n"
                 "  subsection Dirichlet 2\n    set Boundary id = 5\n"
                 "    set Translation = 0, 0, -0.02\n  end");
    text.replace(text.find("set Directory    = ."),
                 std::string("set Directory    = .").size(),
                 "set Directory    = .\n  set Base name = pressed");
    std::ostringstream log;
    StaticSimulation   sim(Scene::SceneParameters::from_string(text), log);
    sim.run();
    const StepResults  r(sim.problem(), sim.solution(), 1.);
    const Tensor<1, 3> F   = r.contact.interactions[0].force;
    const Tensor<1, 3> top = r.reactions[2].force;
    const Tensor<1, 3> sum =
      top + F + r.reactions[0].force + r.reactions[1].force;
    deallog << "pressed by the clamped top face: contact force z " << F[2]
            << ", " << r.reactions[2].name << " z + contact force z "
            << error_bound(std::abs(top[2] + F[2]) / F[2], -8)
            << ", symmetry reactions x " << r.reactions[0].force[0] << " y "
            << r.reactions[1].force[1] << ", sum of all forces "
            << error_bound(sum.norm() / F[2], -8) << std::endl;
    print_integrated_pressure(r, F[2]);
    const auto row = last_row("pressed-statistics.csv");
    deallog << "  statistics file, last row: load factor "
            << row.at("load_factor") << ", obstacle0_plane_Fz - contact force "
            << error_bound(std::abs(row.at("obstacle0_plane_Fz") - F[2]) / F[2],
                           -14)
            << ", dirichlet2_boundary5_Fz + contact force "
            << error_bound(std::abs(row.at("dirichlet2_boundary5_Fz") + F[2]) /
                             F[2],
                           -8)
            << ", columns " << row.size() << std::endl;
  }

  // The augmented Lagrangian (doc/theory/05-contact.md, sec. 6.1): the
  // penalty 100 times smaller than the default 1e3, where the plain penalty
  // lets the block sink by p / eps = 1, twice its height; the multipliers
  // take the pressure and the penetration falls below 1e-6 of the block's
  // height (0.5). Without quasi-viscosity (it damps every solve again after
  // an update) and with load steps of 0.1.
  for (const bool augmented : {false, true})
    {
      std::string text =
        scene("    set Type = plane\n    set Penalty factor = 10");
      text.replace(text.find("  set Quasi-viscosity = true"),
                   std::string("  set Quasi-viscosity = true").size(),
                   "  set Quasi-viscosity = false");
      text += "subsection Load stepping\n  set Maximum increment = 0.1\n"
              "  set Initial increment = 0.1\nend\n";
      if (augmented)
        text += "subsection Contact\n  set Augmented Lagrangian = true\n"
                "  set Penetration tolerance = 5e-7\n"
                "  set Maximum multiplier updates = 40\nend\n";
      std::ostringstream log;
      StaticSimulation   sim(Scene::SceneParameters::from_string(text), log);
      SolveStatistics    stats;
      if (!solve_or_log_static(sim, stats, augmented))
        continue;
      const double d =
        sim.problem().contact_assembler()->max_obstacle_penetration(
          sim.solution());
      const Tensor<1, 3> F =
        sim.problem().contact_assembler()->obstacle_force(sim.solution());
      deallog << "eps = 10, augmented Lagrangian: " << stats.increments
              << " increments, " << stats.multiplier_updates
              << " multiplier updates, " << stats.newton_iterations
              << " Newton iterations; max penetration / height below 1e-6: "
              << (d / 0.5 < 1e-6 ? "yes" : "no") << ", reaction / load - 1 "
              << error_bound(std::abs(F[2] / load - 1.), -8) << std::endl;
    }
}
