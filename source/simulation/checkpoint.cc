#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/output/vtu_file.h>
#include <tissue_contact/scene/parameters.h>
#include <tissue_contact/simulation/checkpoint.h>

#include <deal.II/base/exceptions.h>

#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace TissueContact
{
  namespace
  {
    const char          magic[] = "TissueContact checkpoint\n";
    const std::uint32_t version = 1;
    const std::size_t   magic_n = sizeof(magic) - 1;

    class Writer
    {
    public:
      template <typename T>
      void
      pod(const T &x)
      {
        bytes.append(reinterpret_cast<const char *>(&x), sizeof(T));
      }
      void
      string(const std::string &s)
      {
        pod<std::uint64_t>(s.size());
        bytes += s;
      }
      void
      doubles(const double *x, const std::size_t n)
      {
        pod<std::uint64_t>(n);
        bytes.append(reinterpret_cast<const char *>(x), n * sizeof(double));
      }
      std::string bytes;
    };

    class Reader
    {
    public:
      Reader(const std::string &bytes, const std::string &path)
        : bytes(bytes)
        , path(path)
      {}
      void
      need(const std::size_t n)
      {
        AssertThrow(at + n <= bytes.size(),
                    ExcMessage("the checkpoint '" + path +
                               "' is truncated (the run was killed while "
                               "writing it?)"));
      }
      template <typename T>
      T
      pod()
      {
        need(sizeof(T));
        T x;
        std::memcpy(&x, bytes.data() + at, sizeof(T));
        at += sizeof(T);
        return x;
      }
      std::string
      string()
      {
        const auto n = pod<std::uint64_t>();
        need(n);
        at += n;
        return bytes.substr(at - n, n);
      }
      Vector<double>
      doubles()
      {
        const auto n = pod<std::uint64_t>();
        need(n * sizeof(double));
        Vector<double> v(n);
        if (n > 0)
          std::memcpy(v.data(), bytes.data() + at, n * sizeof(double));
        at += n * sizeof(double);
        return v;
      }
      bool
      done() const
      {
        return at == bytes.size();
      }

    private:
      const std::string &bytes;
      const std::string &path;
      std::size_t        at = 0;
    };

    // s without its leading and trailing blanks
    std::string
    trimmed(const std::string &s)
    {
      const auto first = s.find_first_not_of(' ');
      const auto last  = s.find_last_not_of(' ');
      return first == std::string::npos ? std::string() :
                                          s.substr(first, last - first + 1);
    }
  } // namespace


  std::string
  checkpoint_file(const std::string &directory, const std::string &base_name)
  {
    return directory + "/" + base_name + "-checkpoint.bin";
  }


  void
  check_same_parameters(const Checkpoint  &checkpoint,
                        const std::string &parameters)
  {
    // the entries that matter, as "Section/Subsection/Entry" -> value: not
    // the output folder, not the solver's entries (subsections Newton and
    // Linear solver and theirs). Keyed, so that the column alignment of the
    // printed file does not count
    const auto entries = [](const std::string &text) {
      std::map<std::string, std::string> kept;
      std::vector<std::string>           path;
      unsigned int                       solver_depth = 0; // 0: outside
      std::istringstream                 in(text);
      for (std::string line; std::getline(in, line);)
        {
          const std::string word = trimmed(line);
          if (word.rfind("subsection ", 0) == 0)
            {
              path.push_back(trimmed(word.substr(11)));
              if (solver_depth == 0 && path.size() == 1 &&
                  (path[0] == "Newton" || path[0] == "Linear solver"))
                solver_depth = 1;
              continue;
            }
          if (word == "end")
            {
              if (path.size() == solver_depth)
                solver_depth = 0;
              if (!path.empty())
                path.pop_back();
              continue;
            }
          const auto equals = word.find('=');
          if (solver_depth != 0 || word.rfind("set ", 0) != 0 ||
              equals == std::string::npos)
            continue;
          std::string key;
          for (const auto &section : path)
            key += section + "/";
          key += trimmed(word.substr(4, equals - 4));
          if (key != "Output/Directory")
            kept[key] = trimmed(word.substr(equals + 1));
        }
      return kept;
    };
    // the checkpoint's parameters read by this version of the program, so
    // that an entry added since takes its default, as the current file does
    std::string then;
    try
      {
        then = Scene::SceneParameters::from_string(checkpoint.parameters)
                 .effective_parameters;
      }
    catch (const std::exception &e)
      {
        AssertThrow(false,
                    ExcMessage(std::string("the checkpoint's parameters "
                                           "cannot be read by this version "
                                           "of the program: ") +
                               error_message(e)));
      }
    const auto            a = entries(then), b = entries(parameters);
    std::set<std::string> keys;
    for (const auto *m : {&a, &b})
      for (const auto &entry : *m)
        keys.insert(entry.first);
    for (const auto &key : keys)
      {
        const auto        x = a.find(key), y = b.find(key);
        const std::string was = x == a.end() ? "(none)" : x->second;
        const std::string now = y == b.end() ? "(none)" : y->second;
        AssertThrow(was == now,
                    ExcMessage("the parameter file differs from the one of "
                               "the run that wrote the checkpoint: " +
                               key + " = " + now + " instead of " + was +
                               "; restart with the same parameters (only "
                               "the entries of Newton and Linear solver may "
                               "change)"));
      }
  }


  void
  Checkpoint::write(const std::string &path) const
  {
    Writer w;
    w.bytes.append(magic, magic_n);
    w.pod(version);
    w.string(kind);
    w.string(parameters);
    w.pod<std::uint64_t>(step);
    w.pod<std::uint64_t>(scalars.size());
    for (const auto &[name, value] : scalars)
      {
        w.string(name);
        w.pod(value);
      }
    w.pod<std::uint64_t>(vectors.size());
    for (const auto &[name, v] : vectors)
      {
        w.string(name);
        w.doubles(v.data(), v.size());
      }
    for (const auto *records : {&vtu_records, &surface_records})
      {
        w.pod<std::uint64_t>(records->size());
        for (const auto &[time, file] : *records)
          {
            w.pod(time);
            w.string(file);
          }
      }
    w.pod<std::uint64_t>(file_sizes.size());
    for (const auto &[name, size] : file_sizes)
      {
        w.string(name);
        w.pod(size);
      }
    Output::write_file_atomically(path, w.bytes);
  }


  Checkpoint
  Checkpoint::read(const std::string &path)
  {
    std::ifstream in(path, std::ios::binary);
    AssertThrow(in.good(),
                ExcMessage("there is no checkpoint '" + path +
                           "' to restart from (a run writes one after every "
                           "Output/Checkpoint every n steps-th converged "
                           "step; give the output folder of that run)"));
    std::ostringstream s;
    s << in.rdbuf();
    const std::string bytes = s.str();
    AssertThrow(bytes.compare(0, magic_n, magic) == 0,
                ExcMessage("'" + path + "' is not a TissueContact checkpoint"));
    Reader r(bytes, path);
    r.need(magic_n);
    for (std::size_t i = 0; i < magic_n; ++i)
      r.pod<char>();
    const auto v = r.pod<std::uint32_t>();
    AssertThrow(v == version,
                ExcMessage("the checkpoint '" + path + "' has version " +
                           std::to_string(v) + "; this program reads version " +
                           std::to_string(version)));
    Checkpoint c;
    c.kind       = r.string();
    c.parameters = r.string();
    c.step       = r.pod<std::uint64_t>();
    for (auto n = r.pod<std::uint64_t>(); n > 0; --n)
      {
        const std::string name = r.string();
        c.scalars[name]        = r.pod<double>();
      }
    for (auto n = r.pod<std::uint64_t>(); n > 0; --n)
      {
        const std::string name = r.string();
        c.vectors[name]        = r.doubles();
      }
    for (auto *records : {&c.vtu_records, &c.surface_records})
      for (auto n = r.pod<std::uint64_t>(); n > 0; --n)
        {
          const double time = r.pod<double>();
          records->emplace_back(time, r.string());
        }
    for (auto n = r.pod<std::uint64_t>(); n > 0; --n)
      {
        const std::string name = r.string();
        c.file_sizes[name]     = r.pod<std::uint64_t>();
      }
    AssertThrow(r.done(),
                ExcMessage("the checkpoint '" + path +
                           "' has data after its end: not a checkpoint of "
                           "this program"));
    return c;
  }


  double
  Checkpoint::scalar(const std::string &name) const
  {
    const auto it = scalars.find(name);
    AssertThrow(it != scalars.end(),
                ExcMessage("the checkpoint lacks the value '" + name + "'"));
    return it->second;
  }


  const Vector<double> &
  Checkpoint::vector(const std::string &name, const std::size_t size) const
  {
    const auto it = vectors.find(name);
    AssertThrow(it != vectors.end(),
                ExcMessage("the checkpoint lacks the vector '" + name + "'"));
    AssertThrow(it->second.size() == size,
                ExcMessage("the checkpoint's vector '" + name + "' has " +
                           std::to_string(it->second.size()) +
                           " entries, the scene " + std::to_string(size) +
                           ": a checkpoint of another mesh or degree"));
    return it->second;
  }
} // namespace TissueContact
