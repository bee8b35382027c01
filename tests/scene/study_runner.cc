// The study runner (contrib/study.py, doc/users/choosing.md): a sweep of
// the mesh of a small cantilever under its own weight, run by the program,
// three values of which Skip leaves two cases. Checks that the CSV has the
// expected columns and one row per case, that both cases ran, that the finest
// case is the reference (no error) and the other has its relative error against
// it, computed here again from the two quantities, and that the figure was
// written.

#include "../tests.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace dealii;
using namespace TissueContactTests;

namespace
{
  /** The fields of one CSV line (no quoted commas in the columns read). */
  std::vector<std::string>
  fields(const std::string &line)
  {
    std::vector<std::string> out;
    std::string              field;
    bool                     quoted = false;
    for (const char c : line)
      if (c == '"')
        quoted = !quoted;
      else if (c == ',' && !quoted)
        {
          out.push_back(field);
          field.clear();
        }
      else
        field += c;
    out.push_back(field);
    return out;
  }
} // namespace

int
main()
{
  initlog();
  std::filesystem::remove_all("study-output");
  std::ofstream("two_cases.prm")
    << "subsection Study\n"
       "  set Sweep     = Mesh/Box subdivisions = 2, 1, 1 | 4, 1, 1 | 8, 2, "
       "2\n"
       "  set Combine   = product\n"
       "  set Skip      = Mesh/Box subdivisions = 2, 1, 1\n"
       "  set Quantity  = strain_energy\n"
       "  set Reference = finest\n"
       "  set Plot      = unknowns, error, loglog\n"
       "end\n"
       "subsection Mesh\n"
       "  set Source           = box\n"
       "  set Box upper corner = 1, 0.25, 0.25\n"
       "end\n"
       "subsection Bodies\n"
       "  subsection Body 0\n"
       "    set Model   = neo-Hookean\n"
       "    set Mu      = 1000\n"
       "    set Lambda  = 1500\n"
       "    set Density = 1\n"
       "  end\n"
       "end\n"
       "subsection Boundary conditions\n"
       "  subsection Dirichlet 0\n"
       "    set Boundary id = 0\n"
       "  end\n"
       "end\n"
       "subsection Loads\n"
       "  set Gravity = 0, 0, -10\n"
       "end\n";
  const int status =
    std::system("python3 " SOURCE_DIR "/../../contrib/study.py two_cases.prm "
                "--program ../../../tissue-contact > study.log 2>&1");
  deallog << "study.py exit code "
          << (WIFEXITED(status) ? WEXITSTATUS(status) : -1) << std::endl;

  std::ifstream csv("study-output/two_cases/two_cases.csv");
  std::string   line;
  std::getline(csv, line);
  const std::vector<std::string> header = fields(line);
  deallog << "columns:";
  for (const auto &h : header)
    deallog << " " << h;
  deallog << std::endl;
  const auto column = [&](const std::string &name) {
    return std::find(header.begin(), header.end(), name) - header.begin();
  };
  std::vector<std::vector<std::string>> rows;
  while (std::getline(csv, line))
    if (!line.empty())
      rows.push_back(fields(line));
  deallog << "rows: " << rows.size() << std::endl;
  if (rows.size() != 2)
    return 0;
  for (const auto &r : rows)
    deallog << "case " << r[0] << ": unknowns " << r[column("unknowns")]
            << ", status " << r[column("status")] << ", Newton iterations "
            << (std::stoi(r[column("newton")]) > 0 ? "> 0" : "0")
            << ", quantity "
            << (std::stod(r[column("quantity")]) > 0. ? "> 0" : "<= 0")
            << std::endl;
  const double coarse = std::stod(rows[0][column("quantity")]);
  const double fine   = std::stod(rows[1][column("quantity")]);
  const double error  = std::stod(rows[0][column("error")]);
  deallog << "coarse case's error against the finest, minus |q - q_ref| / "
             "|q_ref|: "
          << (std::abs(error - std::abs(coarse - fine) / std::abs(fine)) <
                  1e-9 ?
                "< 1e-9" :
                "WRONG")
          << "; reference's error column empty: "
          << (rows[1][column("error")].empty() ? "yes" : "no") << std::endl;
  deallog << "figure written: "
          << (std::filesystem::exists("study-output/two_cases/two_cases.png") ?
                "yes" :
                "no")
          << std::endl;
}
