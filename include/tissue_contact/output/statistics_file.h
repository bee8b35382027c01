#pragma once

#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace TissueContact
{
  namespace Output
  {
    /**
     * The statistics of a run, one CSV row per converged increment or
     * time step (as ASPECT's `statistics` file): the first row's column
     * names are the header, every row is written in full precision
     * (17 significant digits) and flushed, so a run that stops keeps
     * every row it completed. A row whose columns differ from the
     * header's is an internal error.
     */
    class StatisticsFile
    {
    public:
      /** Create (or truncate) @p path, or with @p append continue it (its
       * first line is the header); throws naming it if it cannot be
       * written. */
      explicit StatisticsFile(const std::string &path,
                              const bool         append = false);

      /** Write one row of (column name, value). */
      void
      write_row(const std::vector<std::pair<std::string, double>> &columns);

      /** The path of the file. */
      const std::string &
      path() const
      {
        return file_name;
      }

    private:
      std::string              file_name;
      std::ofstream            out;
      std::vector<std::string> header;
    };
  } // namespace Output
} // namespace TissueContact
