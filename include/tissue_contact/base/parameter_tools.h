#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/patterns.h>

#include <string>
#include <utility>
#include <vector>

namespace TissueContact
{
  using namespace dealii;

  /** Appended to the documentation of every entry that is a 3-vector. */
  inline const std::string vector_pattern_doc = " (three numbers: x, y, z)";

  /** A subsection or entry name as ParameterHandler wrote it in its XML
   * output (every character other than a letter or digit as '_' and two
   * hex digits), back as the prm file spells it. */
  inline std::string
  demangle_xml_name(const std::string &s)
  {
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i)
      if (s[i] == '_' && i + 2 < s.size())
        {
          out += static_cast<char>(std::stoi(s.substr(i + 1, 2), nullptr, 16));
          i += 2;
        }
      else
        out += s[i];
    return out;
  }

  /** The pattern of a 3-vector entry "x, y, z". */
  inline Patterns::List
  vector_pattern()
  {
    return Patterns::List(Patterns::Double(), 3, 3);
  }

  /**
   * Bind the entry @p entry to @p value, which takes one of the named
   * values of @p options: the pattern is the selection of the names, the
   * default is the name of the current @p value, and reading the entry sets
   * @p value (ParameterHandler::add_action). The counterpart of
   * ParameterHandler::add_parameter() for enumerations and flags that the
   * prm file spells as words.
   */
  template <typename T>
  void
  add_selection(ParameterHandler                             &prm,
                const std::string                            &entry,
                T                                            &value,
                const std::vector<std::pair<std::string, T>> &options,
                const std::string                            &documentation)
  {
    std::string names, default_name;
    for (const auto &o : options)
      {
        names += (names.empty() ? "" : "|") + o.first;
        if (o.second == value && default_name.empty())
          default_name = o.first;
      }
    Assert(!default_name.empty(),
           ExcMessage("the current value of '" + entry +
                      "' is not among its options"));
    prm.declare_entry(entry,
                      default_name,
                      Patterns::Selection(names),
                      documentation);
    prm.add_action(entry, [&value, options](const std::string &name) {
      for (const auto &o : options)
        if (o.first == name)
          value = o.second;
    });
  }
} // namespace TissueContact
