// A run stopped by SIGINT while it writes a VTU file: the signal is sent by
// a watcher thread the moment inotify reports that the file of the second
// converged increment was created under its temporary name, i.e. while it
// is being written. The run must finish that file, stop with Interrupted
// naming the signal and where the results are, and leave a PVD that lists
// only complete files (every VTU file in the folder listed, each ending
// with its closing tag), no temporary file, and a statistics row for every
// state written.

#include "../tests.h"
#include "scenes.h"

#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/base/interrupt.h>
#include <tissue_contact/simulation/static_simulation.h>

#include <sys/inotify.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <thread>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

namespace
{
  std::string
  read(const std::string &file)
  {
    std::ifstream      in(file);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  namespace fs = std::filesystem;
  fs::remove_all("interrupted");
  fs::create_directories("interrupted");

  // the watcher: SIGINT when beam-0002.vtu.partial is created
  const int inotify = inotify_init();
  inotify_add_watch(inotify, "interrupted", IN_CREATE);
  std::thread watcher([&]() {
    char buffer[4096];
    for (;;)
      {
        const ssize_t n = ::read(inotify, buffer, sizeof(buffer));
        for (ssize_t i = 0; i < n;)
          {
            const auto *event = reinterpret_cast<inotify_event *>(buffer + i);
            if (event->len > 0 &&
                std::string(event->name) == "beam-0002.vtu.partial")
              {
                kill(getpid(), SIGINT);
                return;
              }
            i += sizeof(inotify_event) + event->len;
          }
      }
  });

  install_interrupt_handlers();
  std::ostringstream screen;
  // the beam's files in Float64: larger, so the signal comes mid-write
  StaticSimulation sim(Scene::SceneParameters::from_string(
                         SceneTests::twisted_beam("interrupted") +
                         "subsection Output\n set Double precision = true\n"
                         "end\n"),
                       screen);
  try
    {
      sim.run();
      deallog << "the run was not interrupted" << std::endl;
    }
  catch (const Interrupted &e)
    {
      deallog << "Interrupted, signal " << (e.signal == SIGINT ? "SIGINT" : "?")
              << ": " << e.what() << std::endl;
    }
  watcher.join();
  close(inotify);

  // the series
  const std::string pvd = read("interrupted/beam.pvd");
  const std::regex  entry("file=\"([^\"]+)\"");
  unsigned int      listed = 0, complete = 0;
  for (auto it = std::sregex_iterator(pvd.begin(), pvd.end(), entry);
       it != std::sregex_iterator();
       ++it)
    {
      ++listed;
      const std::string vtu = read("interrupted/" + (*it)[1].str());
      complete += vtu.size() > 12 &&
                  vtu.compare(vtu.size() - 11, 11, "</VTKFile>\n") == 0;
    }
  unsigned int vtu_files = 0, partial = 0;
  for (const auto &f : fs::directory_iterator("interrupted"))
    {
      const std::string name = f.path().filename().string();
      vtu_files += std::regex_match(name, std::regex(R"(beam-[0-9]+\.vtu)"));
      partial += name.find(".partial") != std::string::npos;
    }
  const std::string csv  = read("interrupted/beam-statistics.csv");
  const auto        rows = std::count(csv.begin(), csv.end(), '\n') - 1;
  deallog << "PVD closed: "
          << (pvd.find("</Collection>") != std::string::npos &&
              pvd.find("</VTKFile>") != std::string::npos)
          << ", states listed " << listed << ", complete " << complete
          << ", VTU files in the folder " << vtu_files
          << ", temporary files left " << partial
          << ", statistics rows >= states: " << (rows >= listed) << std::endl;
}
