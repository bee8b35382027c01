// Numerical stability at the extremes (coarse): each stress case runs a
// small scene and is classified as "converges" (increments or steps, Newton
// iterations), "recovers by cut-back" (how many) or "stops" with the first
// words of its message; every case's statistics (and time history) files
// are checked for a value that is not finite. The cases: Poisson's ratio
// 0.3 ... 0.4999 (and 0.49, 0.4999 with the volume term at the vertices), a
// stiffness ratio of 1e6 between two touching blocks, penalty factors 1 and
// 1e8, a 180 degree twist in one increment, a compression to J = 0.05, time
// steps of 1e-6 and 10, elements of aspect ratio 100. Finally a deliberately
// impossible case, a cube squashed to zero height, run by the program itself:
// it ends with its message and exit code 1, and every state written before the
// failure is complete and listed. doc/users/choosing.md, "Extremes", tabulates
// the full matrix.

#include "../tests.h"
#include "scenes.h"

#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/simulation/dynamic_simulation.h>
#include <tissue_contact/simulation/static_simulation.h>

#include <sys/wait.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

namespace
{
  /** Whether every number in the CSV file of @p folder whose name ends in
   * @p suffix (after its header) is finite. */
  std::string
  finite_csv(const std::string &folder, const std::string &suffix)
  {
    std::string name;
    if (std::filesystem::is_directory(folder))
      for (const auto &f : std::filesystem::directory_iterator(folder))
        if (f.path().string().size() > suffix.size() &&
            f.path().string().substr(f.path().string().size() -
                                     suffix.size()) == suffix)
          name = f.path().string();
    std::ifstream in(name);
    if (!in)
      return "no file";
    std::string line;
    std::getline(in, line);
    unsigned int rows = 0;
    while (std::getline(in, line))
      {
        ++rows;
        std::istringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ',');)
          if (!std::isfinite(std::stod(cell)))
            return "a value that is not finite in row " + std::to_string(rows);
      }
    return std::to_string(rows) + " rows, all finite";
  }

  unsigned int n_cases = 0;

  /** The cause in a failed solve's message: what follows "(last
   * converged: ...): " up to "; the load increment", else the message. */
  std::string
  cause(const std::string &message)
  {
    const auto from = message.find("): ");
    const auto to   = message.find("; the load increment");
    return from != std::string::npos && to != std::string::npos && to > from ?
             message.substr(from + 3, to - from - 3) :
             message;
  }

  /** Run @p prm into its own folder with @p run (given the parameters and
   * the log, it returns the outcome: "converges, ..." or "recovers by
   * cut-back (n), ..."), or "stops: <cause>" if it throws; log the outcome
   * and whether the folder's CSV file ending in @p csv holds only finite
   * numbers. */
  template <typename Run>
  void
  run_case(const std::string &name,
           const std::string &prm,
           const std::string &csv,
           const Run         &run)
  {
    const std::string dir = "case-" + std::to_string(n_cases++);
    // no file of an earlier run of the test may stand in for this one's
    std::filesystem::remove_all(dir);
    std::ostringstream log;
    std::string        outcome;
    try
      {
        outcome = run(Scene::SceneParameters::from_string(
                        prm + "subsection Output\n  set Directory = " + dir +
                        "\n  set Write VTU = false\n"
                        "  set Print timing = false\nend\n"),
                      log);
      }
    catch (const std::exception &e)
      {
        outcome = "stops: " + cause(error_message(e));
      }
    deallog << name << ": " << outcome << "; "
            << (csv == "-time.csv" ? "time history " : "statistics ")
            << finite_csv(dir, csv) << std::endl;
  }

  std::string
  classify(const unsigned int cutbacks)
  {
    return cutbacks > 0 ?
             "recovers by cut-back (" + std::to_string(cutbacks) + "), " :
             std::string("converges, ");
  }

  /** A static scene. */
  void
  static_case(const std::string &name, const std::string &prm)
  {
    run_case(name,
             prm,
             "-statistics.csv",
             [](const Scene::SceneParameters &p, std::ostream &log) {
               StaticSimulation      sim(p, log);
               const SolveStatistics s = sim.run();
               return classify(s.cutbacks) + std::to_string(s.increments) +
                      " increments, " + std::to_string(s.newton_iterations) +
                      " Newton iterations" +
                      (s.rounding_convergences > 0 ?
                         ", " + std::to_string(s.rounding_convergences) +
                           " converged to rounding" :
                         std::string());
             });
  }

  /** A dynamic scene: steps, cut-backs and iterations from its summary. */
  void
  dynamic_case(const std::string &name, const std::string &prm)
  {
    run_case(name,
             prm,
             "-time.csv",
             [](const Scene::SceneParameters &p, std::ostringstream &log) {
               DynamicSimulation sim(p, log);
               sim.run();
               std::smatch       m;
               const std::string text = log.str();
               std::regex_search(text,
                                 m,
                                 std::regex(
                                   "in (\\d+) steps \\((\\d+) cut "
                                   "back\\), (\\d+) Newton iterations"));
               return classify(std::stoi(m[2].str())) + m[1].str() +
                      " steps, " + m[3].str() + " Newton iterations";
             });
  }

  std::string
  cantilever(const double       nu,
             const std::string &box          = "1, 0.2, 0.2",
             const std::string &subdivisions = "10, 2, 2")
  {
    const double mu = 100., lambda = 2. * mu * nu / (1. - 2. * nu);
    return "subsection Mesh\n  set Box upper corner = " + box +
           "\n  set Box subdivisions = " + subdivisions +
           "\nend\nsubsection Bodies\n  subsection Body 0\n"
           "    set Model = neo-Hookean\n    set Mu = " +
           std::to_string(mu) + "\n    set Lambda = " + std::to_string(lambda) +
           "\n    set Density = 1\n  end\nend\n"
           "subsection Boundary conditions\n  subsection Dirichlet 0\n"
           "    set Boundary id = 0\n  end\nend\n"
           "subsection Loads\n  set Gravity = 0, 0, -4\nend\n";
  }

  /** The same cantilever in the uncoupled neo-Hookean form with its volume
   * term at the vertices (doc/theory/08-nodal-pressure.md). */
  std::string
  cantilever_nodal_volume(const double nu)
  {
    const double mu = 100., kappa = 2. * mu * (1. + nu) / (3. * (1. - 2. * nu));
    std::string  s         = cantilever(nu);
    const std::string from = "    set Lambda = ";
    s.insert(s.find(from),
             "    set Formulation = uncoupled\n    set Bulk modulus = " +
               std::to_string(kappa) +
               "\n    set Volumetric term = nodal average\n");
    return s;
  }

  std::string
  block_on_plane(const std::string &penalty)
  {
    return "subsection Mesh\n  set Box upper corner = 1, 1, 0.5\n"
           "  set Box subdivisions = 4, 4, 2\nend\n"
           "subsection Bodies\n  subsection Body 0\n    set Mu = 100\n"
           "    set Lambda = 100\n  end\nend\n"
           "subsection Boundary conditions\n"
           "  set Number of Dirichlet conditions = 2\n"
           "  set Number of tractions = 1\n"
           "  subsection Dirichlet 0\n    set Boundary id = 0\n"
           "    set Components = x\n  end\n"
           "  subsection Dirichlet 1\n    set Boundary id = 2\n"
           "    set Components = y\n  end\n"
           "  subsection Traction 0\n    set Boundary id = 5\n"
           "    set Traction = 0, 0, -10\n  end\nend\n"
           "subsection Contact\n  set Contact surfaces = 4\n"
           "  set Number of obstacles = 1\n  subsection Obstacle 0\n"
           "    set Penalty factor = " +
           penalty +
           "\n  end\nend\n"
           "subsection Newton\n  set Quasi-viscosity = true\n"
           "  set Maximum line search halvings = 25\nend\n";
  }

  /** The falling block of prm/falling_block.prm (touching the plane after
   * 0.14 s), integrated for five steps of @p dt. */
  std::string
  falling_block(const std::string &dt)
  {
    return "subsection Mesh\n  set Box lower corner = 0, 0, 0.1\n"
           "  set Box upper corner = 0.2, 0.2, 0.3\n"
           "  set Box subdivisions = 4, 4, 4\nend\n"
           "subsection Bodies\n  subsection Body 0\n    set Mu = 100\n"
           "    set Lambda = 100\n    set Density = 1\n  end\nend\n"
           "subsection Boundary conditions\n"
           "  set Number of Dirichlet conditions = 0\nend\n"
           "subsection Loads\n  set Gravity = 0, 0, -10\nend\n"
           "subsection Contact\n  set Contact surfaces = 4\n"
           "  set Number of obstacles = 1\n  subsection Obstacle 0\n"
           "    set Penalty factor = 1e3\n  end\nend\n"
           "subsection Time integration\n  set Analysis = dynamic\n"
           "  set Scheme = Newmark\n  set Time step = " +
           dt + "\n  set End time = " + std::to_string(5. * std::stod(dt)) +
           "\n  set Rayleigh alpha = 5\n  set Output interval = " + dt +
           "\nend\n";
  }

  /** A unit cube on its bottom (z = 0: fixed), its top (z = 1) moved
   * down by @p squash, Mooney-Rivlin (its barrier keeps J > 0). */
  std::string
  squashed_cube(const double squash)
  {
    return "subsection Mesh\n  set Box subdivisions = 2, 2, 2\nend\n"
           "subsection Bodies\n  subsection Body 0\n"
           "    set Model = Mooney-Rivlin\n    set C1 = 5\n    set C2 = 1\n"
           "    set a = 50\n  end\nend\n"
           "subsection Boundary conditions\n"
           "  set Number of Dirichlet conditions = 2\n"
           "  subsection Dirichlet 0\n    set Boundary id = 4\n  end\n"
           "  subsection Dirichlet 1\n    set Boundary id = 5\n"
           "    set Translation = 0, 0, -" +
           std::to_string(squash) + "\n  end\nend\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  for (const double nu : {0.3, 0.45, 0.49, 0.4999})
    static_case("nu = " + std::to_string(nu).substr(0, 6) +
                  ", cantilever under gravity",
                cantilever(nu));
  for (const double nu : {0.49, 0.4999})
    static_case("nu = " + std::to_string(nu).substr(0, 6) +
                  ", the same, uncoupled, volume term at the vertices",
                cantilever_nodal_volume(nu));

  {
    // the stacked blocks of prm/stacked_blocks.prm, the upper one 1e6 times
    // stiffer than the lower
    std::string       prm   = project_prm("stacked_blocks.prm");
    const std::string lower = "    set Name        = upper\n"
                              "    set Material id = 2\n"
                              "    set Model       = neo-Hookean\n"
                              "    set Mu          = 100\n"
                              "    set Lambda      = 100\n";
    prm.replace(prm.find(lower),
                lower.size(),
                "    set Name        = upper\n    set Material id = 2\n"
                "    set Model       = neo-Hookean\n    set Mu          = 1e8\n"
                "    set Lambda      = 1e8\n");
    static_case("stiffness ratio 1e6 between touching blocks", prm);
    // without the quasi-viscosity, whose diagonal scales with the stiff
    // block's modulus: Newton reaches the residual's rounding floor
    prm.replace(prm.find("set Quasi-viscosity = true"),
                std::string("set Quasi-viscosity = true").size(),
                "set Quasi-viscosity = false");
    static_case("stiffness ratio 1e6, no quasi-viscosity", prm);
  }

  for (const std::string eps : {"1", "1e8"})
    static_case("penalty " + eps + ", block on a plane", block_on_plane(eps));

  {
    std::string prm = SceneTests::twisted_beam(".");
    prm.replace(prm.find("set Rotation angle  = 120"),
                std::string("set Rotation angle  = 120").size(),
                "set Rotation angle  = 180");
    prm.replace(prm.find("set Initial increment = 0.125"),
                std::string("set Initial increment = 0.125").size(),
                "set Initial increment = 1");
    static_case("180 degree twist asked in one increment", prm);
  }

  static_case("compression to J = 0.05 (top moved down by 0.95)",
              squashed_cube(0.95));

  for (const std::string dt : {"1e-6", "10"})
    dynamic_case("time step " + dt + ", falling block (Newmark, 5 steps)",
                 falling_block(dt));

  static_case("elements of aspect ratio 100 (plate 1 x 1 x 0.01)",
              cantilever(0.3, "1, 1, 0.01", "10, 10, 1"));

  // the impossible case, by the program: squashed to zero height
  {
    const std::string dir = "impossible";
    std::filesystem::remove_all(dir);
    std::ofstream(dir + ".prm")
      << squashed_cube(1.) << "subsection Output\n  set Directory = " << dir
      << "\nend\n";
    const std::string program = "../../../tissue-contact";
    const int         status  = std::system(
      (program + " " + dir + ".prm > " + dir + ".log 2>&1").c_str());
    std::ifstream log(dir + ".log");
    std::string   line, error;
    while (std::getline(log, line))
      if (line.find("error:") != std::string::npos)
        error = line.substr(line.find("error:"));
    deallog << "cube squashed to zero height (the program): exit code "
            << (WIFEXITED(status) ? WEXITSTATUS(status) : -1) << ", " << error
            << std::endl;
    // every VTU the PVD lists exists and is complete; the statistics hold a
    // row per state
    std::ifstream    pvd(dir + "/solution.pvd");
    std::string      text((std::istreambuf_iterator<char>(pvd)),
                     std::istreambuf_iterator<char>());
    unsigned int     listed = 0, complete = 0;
    const std::regex file("file=\"([^\"]+)\"");
    for (std::sregex_iterator i(text.begin(), text.end(), file), end; i != end;
         ++i)
      {
        ++listed;
        std::ifstream vtu(dir + "/" + (*i)[1].str());
        std::string   content((std::istreambuf_iterator<char>(vtu)),
                            std::istreambuf_iterator<char>());
        complete += content.find("</VTKFile>") != std::string::npos;
      }
    deallog << "  states kept: " << listed << " listed, " << complete
            << " complete, PVD closed: "
            << (text.find("</VTKFile>") != std::string::npos ? "yes" : "no")
            << "; statistics " << finite_csv(dir, "-statistics.csv")
            << std::endl;
  }
}
