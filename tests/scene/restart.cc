// Checkpoint and restart: a static run (a beam twisted 120 degrees in
// growing increments) and a dynamic one (a block dropped onto a rigid plane,
// Newmark, through the impact) are each run uninterrupted, then run again
// in a child process that kills itself with SIGKILL the moment its k-th
// checkpoint appears (an inotify watcher thread; the next step takes
// thousands of times longer than the notification), and continued from
// that checkpoint. The restarted
// run must end with the same solution (difference printed) and write the
// same files: every VTU file and the PVD byte for byte, the statistics file
// equal but for its wall-time column, the convergence log (static) and the
// time history (dynamic) equal. A checkpoint of other parameters is
// refused, naming the difference.

#include "../dynamics/scenes.h"
#include "../tests.h"
#include "scenes.h"

#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/simulation/checkpoint.h>
#include <tissue_contact/simulation/dynamic_simulation.h>
#include <tissue_contact/simulation/static_simulation.h>

#include <sys/inotify.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

namespace
{
  std::string
  block(const std::string &directory)
  {
    return std::string(DynamicsTestScenes::falling_block) + R"(
subsection Time integration
  set Analysis        = dynamic
  set Scheme          = Newmark
  set Time step       = 0.01
  set End time        = 0.25
  set Rayleigh alpha  = 5
  set Output interval = 0.05
end
subsection Output
  set Write VTU    = true
  set Directory    = )" +
           directory + R"(
  set Base name    = block
end
)";
  }

  std::string
  scene(const std::string &kind, const std::string &directory)
  {
    return kind == "static" ? SceneTests::twisted_beam(directory) :
                              block(directory);
  }

  /** Run the scene, from the start or from @p restart; the solution. */
  Vector<double>
  run(const std::string &kind,
      const std::string &directory,
      const Checkpoint  *restart = nullptr)
  {
    std::ostringstream log;
    const auto         parameters =
      Scene::SceneParameters::from_string(scene(kind, directory));
    if (kind == "static")
      {
        StaticSimulation sim(parameters, log);
        sim.run(restart);
        return sim.problem().displacement(sim.solution());
      }
    DynamicSimulation sim(parameters, log);
    sim.run({}, restart);
    return sim.state().u;
  }

  std::string
  read(const std::string &file)
  {
    std::ifstream      in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

  /** The CSV @p file without column @p skip (-1: none). */
  std::string
  without_column(const std::string &file, const int skip)
  {
    std::istringstream in(read(file));
    std::string        result;
    for (std::string line; std::getline(in, line);)
      {
        std::istringstream cells(line);
        int                i = 0;
        for (std::string cell; std::getline(cells, cell, ','); ++i)
          if (i != skip)
            result += cell + ",";
        result += "\n";
      }
    return result;
  }

  /** Run the scene in a child process (this program, with arguments
   * "child KIND DIR K") that kills itself once its K-th checkpoint is
   * written; returns how the child ended. */
  std::string
  run_and_kill(const char        *program,
               const std::string &kind,
               const std::string &directory,
               const unsigned int k)
  {
    const pid_t child = fork();
    if (child == 0)
      {
        execl(program,
              program,
              "child",
              kind.c_str(),
              directory.c_str(),
              std::to_string(k).c_str(),
              static_cast<char *>(nullptr));
        _exit(127);
      }
    int status = 0;
    waitpid(child, &status, 0);
    return WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL ?
             "killed by SIGKILL" :
             "ended by itself (no checkpoint " + std::to_string(k) + ")";
  }

  /** The child: watch DIR for checkpoints renamed into place, SIGKILL
   * itself at the K-th, and run the scene meanwhile. */
  void
  child(const std::string &kind, const std::string &directory, const int k)
  {
    std::filesystem::create_directories(directory);
    const int inotify = inotify_init();
    inotify_add_watch(inotify, directory.c_str(), IN_MOVED_TO);
    std::thread watcher([=]() {
      char buffer[4096];
      int  seen = 0;
      for (;;)
        {
          const ssize_t n = ::read(inotify, buffer, sizeof(buffer));
          for (ssize_t i = 0; i < n;)
            {
              const auto *event = reinterpret_cast<inotify_event *>(buffer + i);
              if (event->len > 0 &&
                  std::string(event->name).find("-checkpoint.bin") !=
                    std::string::npos &&
                  ++seen == k)
                kill(getpid(), SIGKILL);
              i += sizeof(inotify_event) + event->len;
            }
        }
    });
    watcher.detach();
    run(kind, directory);
  }
} // namespace

int
main(int argc, char **argv)
{
  if (argc == 5 && std::string(argv[1]) == "child")
    {
      Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      child(argv[2], argv[3], std::stoi(argv[4]));
      return 0;
    }
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  namespace fs = std::filesystem;

  for (const std::string kind : {"static", "dynamic"})
    {
      const std::string base = kind == "static" ? "beam" : "block";
      fs::remove_all("whole");
      fs::remove_all("killed");
      const Vector<double> whole = run(kind, "whole");
      const unsigned int   k     = kind == "static" ? 3 : 10;
      const std::string    ended = run_and_kill(argv[0], kind, "killed", k);
      const Checkpoint     checkpoint =
        Checkpoint::read(checkpoint_file("killed", base));
      const Vector<double> continued = run(kind, "killed", &checkpoint);
      Vector<double>       difference(whole);
      difference -= continued;
      // (the kill may come a step late on a loaded machine: any checkpoint
      // from the k-th on serves)
      deallog << kind << ": the run " << ended << " after checkpoint " << k
              << " (its step >= " << k << ": " << (checkpoint.step >= k)
              << "), restarted: largest difference from the uninterrupted "
                 "run "
              << error_bound(difference.linfty_norm(), -14) << std::endl;

      unsigned int n_files = 0, equal = 0;
      for (const auto &f : fs::directory_iterator("whole"))
        {
          const std::string name = f.path().filename().string();
          if (name.find(".vtu") == std::string::npos &&
              name.find(".pvd") == std::string::npos)
            continue;
          ++n_files;
          equal += read("whole/" + name) == read("killed/" + name);
        }
      unsigned int n_killed = 0;
      for (const auto &f : fs::directory_iterator("killed"))
        n_killed += f.path().extension() == ".vtu";
      const std::string history =
        kind == "static" ? "-convergence.csv" : "-time.csv";
      deallog << "  VTU and PVD files " << n_files << ", equal byte for byte "
              << equal << ", VTU files in the restarted folder " << n_killed
              << "; statistics equal but for wall time: "
              << (without_column("whole/" + base + "-statistics.csv",
                                 kind == "static" ? 2 : -1) ==
                  without_column("killed/" + base + "-statistics.csv",
                                 kind == "static" ? 2 : -1))
              << ", " << base + history << " equal: "
              << (read("whole/" + base + history) ==
                  read("killed/" + base + history))
              << std::endl;
    }

  // a checkpoint of other parameters
  try
    {
      const Checkpoint checkpoint =
        Checkpoint::read(checkpoint_file("killed", "block"));
      std::string other = block("killed");
      other.replace(other.find("set Mu      = 100"), 17, "set Mu      = 200");
      check_same_parameters(
        checkpoint,
        Scene::SceneParameters::from_string(other).effective_parameters);
      deallog << "other parameters: accepted" << std::endl;
    }
  catch (const std::exception &e)
    {
      deallog << "other parameters: " << error_message(e) << std::endl;
    }

  // other solver entries (Newton, Linear solver) are accepted; with them,
  // another material is still refused
  const Checkpoint block_checkpoint =
    Checkpoint::read(checkpoint_file("killed", "block"));
  std::string solver = block("killed") + "subsection Newton\n"
                                         "  set Residual tolerance = 1e-5\n"
                                         "end\n"
                                         "subsection Linear solver\n"
                                         "  set Type = GMRES+AMG\n"
                                         "end\n";
  for (const bool other_material : {false, true})
    try
      {
        if (other_material)
          solver.replace(solver.find("set Mu      = 100"),
                         17,
                         "set Mu      = 200");
        check_same_parameters(
          block_checkpoint,
          Scene::SceneParameters::from_string(solver).effective_parameters);
        deallog << "other solver entries"
                << (other_material ? " and another material" : "")
                << ": accepted" << std::endl;
      }
    catch (const std::exception &e)
      {
        deallog << "other solver entries"
                << (other_material ? " and another material" : "") << ": "
                << error_message(e) << std::endl;
      }

  // a checkpoint written before an entry existed (Stiffness quadrature,
  // here at its default) is read with that entry's default; one with an
  // entry this version does not know is refused, naming it
  for (const bool unknown : {false, true})
    try
      {
        Checkpoint         older = block_checkpoint;
        std::string        text;
        std::istringstream in(older.parameters);
        for (std::string line; std::getline(in, line);)
          if (line.find("Stiffness quadrature") == std::string::npos)
            text += line + "\n";
          else if (unknown)
            text += line + "\n  set Retired entry = 1\n";
        older.parameters = text;
        check_same_parameters(older,
                              Scene::SceneParameters::from_string(
                                block("killed"))
                                .effective_parameters);
        deallog << (unknown ? "a checkpoint with an unknown entry" :
                              "a checkpoint without a newer entry")
                << ": accepted" << std::endl;
      }
    catch (const std::exception &e)
      {
        deallog << (unknown ? "a checkpoint with an unknown entry" :
                              "a checkpoint without a newer entry")
                << ": " << error_message(e) << std::endl;
      }
}
