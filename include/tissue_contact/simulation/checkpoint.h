#pragma once

#include <deal.II/lac/vector.h>

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace TissueContact
{
  using namespace dealii;

  /**
   * What a run needs to continue after it was killed exactly as it would
   * have gone on (doc/users/running.md, "Checkpoint and restart"): written
   * by the drivers after every Output/Checkpoint every n steps-th converged
   * increment or time step to <base>-checkpoint.bin (a plain binary file
   * with a version header, replaced atomically), read by `tissue-contact
   * --restart DIR scene.prm`.
   *
   * It holds the run's kind and effective parameters (a restart with other
   * parameters is refused), the number of converged steps, named scalars
   * (static: the load factor, the one before it, the next increment's
   * size, the counts; dynamic: the time, the next step, the counts, the
   * dissipated energy, the next output time) and vectors (static: u and
   * the previous state of the two-point predictor; dynamic: u, v, a), the
   * VTU series written so far and the sizes of the CSV files at that
   * moment (the restarted run cuts them there and appends).
   */
  struct Checkpoint
  {
    std::string                                 kind;
    std::string                                 parameters;
    unsigned int                                step = 0;
    std::map<std::string, double>               scalars;
    std::map<std::string, Vector<double>>       vectors;
    std::vector<std::pair<double, std::string>> vtu_records, surface_records;
    std::map<std::string, std::uint64_t>        file_sizes;

    /** Write to @p path (atomically: the old checkpoint stays until the new
     * one is complete). */
    void
    write(const std::string &path) const;

    /** Read @p path; throws naming the file and what is wrong (missing,
     * not a checkpoint, another version, truncated). */
    static Checkpoint
    read(const std::string &path);

    /** The scalar @p name; throws naming it if the file lacks it. */
    double
    scalar(const std::string &name) const;

    /** The vector @p name of @p size entries; throws if missing or of
     * another size (a checkpoint of another mesh). */
    const Vector<double> &
    vector(const std::string &name, const std::size_t size) const;
  };

  /** Throw, naming the first difference, if @p parameters (a scene's
   * effective parameters) differ from those of the run that wrote
   * @p checkpoint, aside from the output folder (Output/Directory) and the
   * entries of the subsections "Newton" and "Linear solver": how the
   * equations are solved may change on a restart (a looser tolerance, another
   * linear solver), the equations and the load path may not. */
  void
  check_same_parameters(const Checkpoint  &checkpoint,
                        const std::string &parameters);

  /** The checkpoint file of a run in @p directory with base name
   * @p base_name. */
  std::string
  checkpoint_file(const std::string &directory, const std::string &base_name);
} // namespace TissueContact
