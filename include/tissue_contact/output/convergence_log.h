#pragma once

#include <tissue_contact/base/solve_statistics.h>

#include <fstream>
#include <ostream>
#include <string>

namespace TissueContact
{
  namespace Output
  {
    /**
     * The Newton history: one table row per iteration on @p screen (like
     * step-44) and one CSV line per iteration in @p csv_file with the
     * columns increment, load_factor, iteration, residual_norm, update_norm,
     * step_length, linear_iterations. A cut-back increment is shown as a
     * line of its own. The CSV file is flushed after every line, so a run
     * that stops keeps its history.
     */
    class ConvergenceLog
    {
    public:
      /** With @p append, continue @p csv_file (a restarted run). */
      ConvergenceLog(std::ostream      &screen,
                     const std::string &csv_file,
                     const bool         append = false);

      void
      iteration(const IterationInfo &info);

      void
      cutback(const double load_factor, const std::string &reason);

    private:
      std::ostream &screen;
      std::ofstream csv;
      unsigned int  last_increment = 0;
    };
  } // namespace Output
} // namespace TissueContact
