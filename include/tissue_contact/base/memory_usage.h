#pragma once

#include <string>
#include <utility>
#include <vector>

namespace TissueContact
{
  /**
   * Where the resident memory of this process goes, from the kernel's
   * account of its mappings (/proc/self/status and /proc/self/smaps, Linux
   * only): the program's own data (the heap, anonymous mappings, stacks)
   * and the pages of the shared libraries it maps (deal.II, and what
   * deal.II links: gmsh with OpenCASCADE, Trilinos, PETSc, MPI, ...), which
   * are mostly clean and shared with other processes. All in MiB.
   */
  struct MemoryUsage
  {
    /** False where /proc is not available. */
    bool   available = false;
    double peak = 0., resident = 0., program_data = 0., libraries = 0.;
    /** The libraries' resident pages by library family, largest first. */
    std::vector<std::pair<std::string, double>> largest_libraries;
  };

  /** The current memory usage of this process. */
  MemoryUsage
  memory_usage();

  /** One line for a run's summary: "memory: peak resident ... MiB; now
   * ...: program data ..., shared libraries ... (deal.II ..., ...)", or
   * an empty string where it is not available. */
  std::string
  memory_summary();
} // namespace TissueContact
