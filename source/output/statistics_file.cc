#include <tissue_contact/output/statistics_file.h>

#include <deal.II/base/exceptions.h>

#include <iomanip>
#include <limits>
#include <sstream>

namespace TissueContact
{
  namespace Output
  {
    using namespace dealii;

    StatisticsFile::StatisticsFile(const std::string &path, const bool append)
      : file_name(path)
    {
      if (append)
        {
          std::ifstream in(path);
          std::string   line, cell;
          std::getline(in, line);
          std::istringstream names(line);
          while (std::getline(names, cell, ','))
            header.push_back(cell);
          AssertThrow(!header.empty(),
                      ExcMessage("the statistics file '" + path +
                                 "' to continue has no header"));
        }
      out.open(path, append ? std::ios::app : std::ios::trunc);
      AssertThrow(out.good(),
                  ExcMessage("cannot write the statistics file '" + path +
                             "': check that its folder exists and is "
                             "writable"));
      out << std::setprecision(std::numeric_limits<double>::max_digits10);
    }


    void
    StatisticsFile::write_row(
      const std::vector<std::pair<std::string, double>> &columns)
    {
      if (header.empty())
        {
          for (unsigned int i = 0; i < columns.size(); ++i)
            {
              header.push_back(columns[i].first);
              out << (i > 0 ? "," : "") << columns[i].first;
            }
          out << '\n';
        }
      Assert(columns.size() == header.size(),
             ExcMessage("a statistics row with other columns than the "
                        "header"));
      for (unsigned int i = 0; i < columns.size(); ++i)
        out << (i > 0 ? "," : "") << columns[i].second;
      out << std::endl;
      AssertThrow(out.good(),
                  ExcMessage("writing the statistics file '" + file_name +
                             "' failed (is the disk full?)"));
    }
  } // namespace Output
} // namespace TissueContact
