// Benchmark (not a test): the knee-scale scene, start to end, on 1 and 2
// threads. By default prm/knee_flexion.prm, the knee at the sources' scale
// (meshes/knee.geo: 40 295 tetrahedra, 29 706 unknowns, 12 373 contact
// triangles, 150 degrees in 50 increments, doc/users/knee.md); any static
// scene can be given instead, e.g. prm/knee_tube.prm, the knee-scale tube
// the tables of the README before 2026-12-05 were measured on. Prints, per
// thread count, the wall time of the set-up (meshing included) and of the
// run, the increments and iterations, the time split, and the peak
// memory (resident set) of the process.
//
//   cmake --build build --target performance
//   build/tests/performance/knee [--quick] [scene.prm]
//
// --quick meshes the knee as the test scene/knee_flexion does (h 0.06,
// 5 elements per 2 pi, the patella refined twice) and the tube at h 0.012
// (7 294 tetrahedra) instead of 0.0062; other scenes have no quick mesh.
// Each thread count runs in its own process (the peak memory is that
// run's). Needs gmsh on the PATH for a Source = geo scene.

#include <tissue_contact/simulation/static_simulation.h>

#include <deal.II/base/multithread_info.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <sys/resource.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

using namespace dealii;
using namespace TissueContact;

namespace
{
  // the columns of the time split, from the run's timer sections
  // (doc/users/running.md)
  const std::vector<std::string> columns = {"elastic",
                                            "search",
                                            "kernels",
                                            "insertion",
                                            "energy",
                                            "pattern",
                                            "rebuild",
                                            "solve",
                                            "output"};

  double
  section(const std::map<std::string, double> &t, const std::string &name)
  {
    const auto it = t.find(name);
    return it == t.end() ? 0. : it->second;
  }

  // where the children leave their rows of the second table
  const std::string evaluations_file =
    (std::filesystem::temp_directory_path() /
     "tissue_contact_knee_benchmark_evaluations.txt")
      .string();

  // One run in this process: print one table row.
  int
  run_one(const std::string &prm_file, const bool quick)
  {
    const std::string source(SOURCE_DIR "/../..");
    std::ifstream     in(prm_file);
    AssertThrow(in, ExcMessage("cannot read " + prm_file));
    std::stringstream text;
    text << in.rdbuf();
    std::string prm = text.str();
    // paths relative to the prm file's folder
    const std::string folder =
      std::filesystem::absolute(prm_file).parent_path().string();
    for (std::size_t at = prm.find("../"); at != std::string::npos;
         at             = prm.find("../", at + folder.size() + 4))
      prm.insert(at, folder + "/");
    if (quick)
      {
        // the coarse mesh of the scene's geometry (its Mesh/File entry)
        const std::string geometry =
          std::filesystem::path(
            Scene::SceneParameters::from_string(prm).mesh.file)
            .filename()
            .string();
        const std::string options =
          geometry == "knee_tube.geo" ?
            "-setnumber h 0.012" :
          geometry == "knee.geo" ?
            "-setnumber h 0.06 -setnumber n_2pi 5 -setnumber pat_refine 2" :
            "";
        AssertThrow(!options.empty(),
                    ExcMessage("--quick knows the coarse meshes of "
                               "meshes/knee.geo and meshes/knee_tube.geo "
                               "only; " +
                               prm_file + " uses neither"));
        prm += "\nsubsection Mesh\n  set Gmsh options = " + options + "\nend\n";
      }
    const std::string out_dir =
      (std::filesystem::temp_directory_path() / "tissue_contact_knee_benchmark")
        .string();
    prm += "\nsubsection Output\n  set Directory = " + out_dir +
           "\n  set Print timing = false\nend\n";

    std::ostringstream evaluations;
    Timer              setup;
    std::ostringstream log;
    StaticSimulation   sim(Scene::SceneParameters::from_string(prm), log);
    const double       t_setup = setup.wall_time();
    SolveStatistics    s;
    try
      {
        s = sim.run();
      }
    catch (const std::exception &e)
      {
        std::cout << "run failed: " << e.what() << "\n";
        return 1;
      }
    const auto  &t         = sim.section_times();
    const auto  *contact   = sim.problem().contact_assembler();
    const double search    = section(t, "contact: search"),
                 kernels   = section(t, "contact: kernels"),
                 insertion = section(t, "contact: insertion"),
                 energy    = section(t, "contact: energy"),
                 pattern   = section(t, "contact: sparsity check"),
                 rebuild   = section(t, "contact: pattern build");
    const double elastic   = section(t, "assembly") - search - kernels -
                           insertion - energy - pattern - rebuild;
    rusage usage;
    getrusage(RUSAGE_SELF, &usage);

    // one evaluation of each kind at the end state (ms, mean of 3)
    Problem    &problem = sim.problem();
    const auto  n       = problem.n_dofs();
    const auto &u       = sim.solution();
    // the pattern the run built last served its last tangent; the converged
    // state may have contact pairs it lacks
    problem.update_sparsity_pattern(u);
    SparseMatrix<double> K(problem.sparsity_pattern());
    Vector<double>       R(n);
    const auto           mean_ms = [](const auto &f) {
      Timer timer;
      for (unsigned int r = 0; r < 3; ++r)
        f();
      return 1e3 * timer.wall_time() / 3;
    };
    // the finite element pattern alone, for comparison
    DynamicSparsityPattern dsp(problem.discretization().n_dofs());
    DoFTools::make_sparsity_pattern(problem.discretization().dof_handler, dsp);
    SparsityPattern fe_pattern;
    fe_pattern.copy_from(dsp);
    evaluations << std::left << std::setw(8) << MultithreadInfo::n_threads()
                << std::fixed << std::setprecision(1) << std::setw(12)
                << mean_ms([&]() { problem.assemble(u, 1., R, &K); })
                << std::setw(12)
                << mean_ms([&]() { problem.assemble(u, 1., R, nullptr); })
                << std::setw(12) << mean_ms([&]() { problem.energy(u, 1.); })
                << std::setw(12) << mean_ms([&]() {
                     if (contact)
                       contact->assemble(problem.displacement(u), R, &K);
                   })
                << std::setw(12) << mean_ms([&]() {
                     if (contact)
                       contact->energy(problem.displacement(u));
                   })
                << std::setw(10)
                << problem.sparsity_pattern().n_nonzero_elements() / 1e6
                << std::setw(10) << fe_pattern.n_nonzero_elements() / 1e6
                << std::setw(10)
                << problem.sparsity_pattern().max_entries_per_row()
                << problem.n_sparsity_patterns() << "\n";

    std::cout << std::left << std::setw(8) << MultithreadInfo::n_threads()
              << std::setw(7)
              << sim.problem().get_scene().triangulation.n_active_cells()
              << std::setw(7) << sim.problem().n_dofs() << std::setw(7)
              << (contact ? contact->n_triangles() : 0) << std::setw(6)
              << s.increments << std::setw(5) << s.cutbacks << std::setw(7)
              << s.newton_iterations << std::setw(8) << s.linear_iterations
              << std::fixed << std::setprecision(1) << std::setw(7) << t_setup
              << std::setw(8) << section(t, "total");
    for (const double v : {elastic,
                           search,
                           kernels,
                           insertion,
                           energy,
                           pattern,
                           rebuild,
                           section(t, "linear solve"),
                           section(t, "output")})
      std::cout << std::setw(10) << v;
    std::cout << usage.ru_maxrss / 1024 << "\n";
    std::ofstream(evaluations_file, std::ios::app) << evaluations.str();
    return 0;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv);
  bool                             quick = false, child = false;
  std::string prm = SOURCE_DIR "/../../prm/knee_flexion.prm";
  for (int i = 1; i < argc; ++i)
    {
      const std::string a = argv[i];
      if (a == "--quick")
        quick = true;
      else if (a == "--child")
        child = true;
      else
        prm = a;
    }
  if (child)
    try
      {
        return run_one(prm, quick);
      }
    catch (const std::exception &e)
      {
        std::cout << "run failed: " << e.what() << "\n";
        return 1;
      }

  std::cout << "The knee-scale scene " << prm << (quick ? " (--quick)" : "")
            << ", start to end. Times in s (wall); elastic: the elastic "
               "assembly and the rest of the Newton loop's assembly "
               "section; search, kernels, insertion: the contact pairs' "
               "search, kernels and matrix insertion; energy: the line "
               "search's contact energies; pattern: the contact sparsity "
               "check; rebuild: the sparsity pattern's rebuilds when it "
               "lacks a contact coupling; memory: peak resident set in MiB\n\n"
            << std::left << std::setw(8) << "threads" << std::setw(7) << "tets"
            << std::setw(7) << "dofs" << std::setw(7) << "tris" << std::setw(6)
            << "incr" << std::setw(5) << "cut" << std::setw(7) << "Newton"
            << std::setw(8) << "linear" << std::setw(7) << "setup"
            << std::setw(8) << "run";
  for (const auto &c : columns)
    std::cout << std::setw(10) << c;
  std::cout << "MiB" << std::endl;
  std::filesystem::remove(evaluations_file);
  int status = 0;
  for (const unsigned int threads : {1u, 2u})
    {
      std::ostringstream cmd;
      cmd << "DEAL_II_NUM_THREADS=" << threads << " " << argv[0] << " --child "
          << (quick ? "--quick " : "") << "'" << prm << "'";
      status |= std::system(cmd.str().c_str());
    }
  std::cout << "\nOne evaluation at the end state (ms): residual and "
               "tangent, residual alone, energy (elasticity and contact), "
               "then the contact part of the first and of the last; the "
               "matrix's nonzeros (millions), those of the finite element "
               "pattern alone, the longest row, and how often the pattern "
               "was built in the run\n\n"
            << std::left << std::setw(8) << "threads" << std::setw(12)
            << "R + K" << std::setw(12) << "R" << std::setw(12) << "energy"
            << std::setw(12) << "contact R+K" << std::setw(12) << "contact W"
            << std::setw(10) << "nnz (M)" << std::setw(10) << "FE nnz"
            << std::setw(10) << "max row"
            << "patterns\n";
  std::ifstream     rows(evaluations_file);
  std::stringstream text;
  text << rows.rdbuf();
  std::cout << text.str();
  return status == 0 ? 0 : 1;
}
