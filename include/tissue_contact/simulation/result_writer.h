#pragma once

#include <tissue_contact/output/statistics_file.h>
#include <tissue_contact/output/vtu_writer.h>
#include <tissue_contact/simulation/checkpoint.h>
#include <tissue_contact/simulation/problem.h>
#include <tissue_contact/simulation/step_results.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace TissueContact
{
  /**
   * What a run writes of its converged states, the same for the static
   * and the dynamic driver (doc/users/output.md): at every converged
   * increment or step a row of <base>-statistics.csv (the step, its load
   * factor or time, the caller's columns, then StepResults::columns():
   * energies, contact forces, areas and penetrations, reactions), and at
   * every Output/Every n steps-th (and the last) the VTU files with the
   * material depth and the contact fields. At the start it removes an
   * earlier run's files with the same base name from the output folder
   * (or refuses: Output/Old results); a restarted run instead continues
   * the files of the checkpoint it starts from: the CSV files cut to their
   * length then, the VTU files written after it removed, the series
   * continued. It also writes the checkpoints (write_checkpoint()).
   */
  class ResultWriter
  {
  public:
    /** A new run, or with @p restart the continuation of one. */
    explicit ResultWriter(const Problem    &problem,
                          const Checkpoint *restart = nullptr);

    /** Record the converged state @p u of step @p step at load factor or
     * time @p time (load factor @p load_factor): the statistics row
     * (@p extra columns after step and time) and, if @p write_vtu, the
     * VTU files. Returns the results. */
    StepResults
    record(const unsigned int                                 step,
           const double                                       time,
           const Vector<double>                              &u,
           const double                                       load_factor,
           const bool                                         write_vtu,
           const std::vector<std::pair<std::string, double>> &extra = {});

    /** Wait until the VTU files of the last record() are written (they
     * are written beside the run); throws if they could not be. */
    void
    finish() const
    {
      if (vtu)
        vtu->finish();
    }

    /** Whether step number @p step (counted from 1) is due for VTU output
     * by Output/Every n steps (the last step is always written by the
     * caller). */
    bool
    due(const unsigned int step) const;

    /** The series (empty if no VTU is written). */
    std::string
    pvd_file() const;

    /** The statistics file. */
    std::string
    statistics_file() const
    {
      return statistics.path();
    }

    /** Whether converged step @p step is due for a checkpoint
     * (Output/Checkpoint every n steps; 0: never). */
    bool
    checkpoint_due(const unsigned int step) const;

    /** Complete @p c with the output's state (the series written, the CSV
     * files' sizes: @p csv_files, each flushed) and the run's parameters,
     * and write it to <base>-checkpoint.bin: at once without VTU output,
     * else on the VTU writing thread once the files of the last record()
     * are complete (finish() waits for it too). */
    void
    write_checkpoint(Checkpoint c, const std::vector<std::string> &csv_files);

  private:
    const Problem                           &problem;
    std::unique_ptr<Output::VtuSeriesWriter> vtu;
    Output::StatisticsFile                   statistics;
  };

  /** Remove from @p directory the files an earlier run with base name
   * @p base_name wrote (its VTU and PVD series, its CSV files and
   * unfinished temporary files), or, if @p refuse, throw naming the first
   * one found. */
  void
  clear_old_results(const std::string &directory,
                    const std::string &base_name,
                    const bool         refuse);
} // namespace TissueContact
