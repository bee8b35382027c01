#include <tissue_contact/base/memory_usage.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

namespace TissueContact
{
  namespace
  {
    /** The family a mapped file belongs to, for the summary. */
    std::string
    family(const std::string &path)
    {
      const std::string name = path.substr(path.rfind('/') + 1);
      if (name.rfind("libdeal.ii", 0) == 0)
        return "deal.II";
      if (name.rfind("libgmsh", 0) == 0 || name.rfind("libTK", 0) == 0)
        return "gmsh and OpenCASCADE";
      if (name.rfind("libtrilinos", 0) == 0)
        return "Trilinos";
      if (name.rfind("libpetsc", 0) == 0)
        return "PETSc";
      if (name.rfind("libtissue_contact", 0) == 0 ||
          name.rfind("tissue-contact", 0) == 0)
        return "TissueContact";
      return "others";
    }
  } // namespace


  MemoryUsage
  memory_usage()
  {
    MemoryUsage   m;
    std::ifstream status("/proc/self/status"), smaps("/proc/self/smaps");
    if (!status || !smaps)
      return m;
    m.available = true;
    std::string line;
    while (std::getline(status, line))
      {
        std::istringstream in(line);
        std::string        key;
        double             kB = 0.;
        in >> key >> kB;
        if (key == "VmHWM:")
          m.peak = kB / 1024.;
        else if (key == "VmRSS:")
          m.resident = kB / 1024.;
      }
    // smaps: a header line per mapping ("start-end perms offset dev inode
    // [path]"), then "Key: value kB" lines, among them Rss
    std::map<std::string, double> by_family;
    std::string                   path;
    while (std::getline(smaps, line))
      {
        std::istringstream in(line);
        std::string        first;
        in >> first;
        if (first.empty())
          continue;
        if (first.back() != ':')
          {
            std::string perms, offset, dev, inode;
            path.clear();
            in >> perms >> offset >> dev >> inode >> path;
          }
        else if (first == "Rss:")
          {
            double kB = 0.;
            in >> kB;
            // files are the mapped libraries and executables; "[heap]",
            // "[stack]" and nameless mappings are the program's data
            if (!path.empty() && path[0] == '/')
              {
                m.libraries += kB / 1024.;
                by_family[family(path)] += kB / 1024.;
              }
            else
              m.program_data += kB / 1024.;
          }
      }
    for (const auto &f : by_family)
      if (f.first != "others")
        m.largest_libraries.push_back(f);
    std::sort(m.largest_libraries.begin(),
              m.largest_libraries.end(),
              [](const auto &a, const auto &b) { return a.second > b.second; });
    if (by_family.count("others"))
      m.largest_libraries.emplace_back("others", by_family["others"]);
    return m;
  }


  std::string
  memory_summary()
  {
    const MemoryUsage m = memory_usage();
    if (!m.available)
      return "";
    std::ostringstream out;
    out << std::fixed << std::setprecision(0) << "memory: peak resident "
        << m.peak << " MiB; now " << m.resident << " MiB: program data "
        << m.program_data << " MiB, shared libraries " << m.libraries
        << " MiB (";
    for (unsigned int i = 0; i < m.largest_libraries.size(); ++i)
      out << (i > 0 ? ", " : "") << m.largest_libraries[i].first << " "
          << m.largest_libraries[i].second;
    out << "; their pages are mostly clean and shared)";
    return out.str();
  }
} // namespace TissueContact
