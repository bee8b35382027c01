// The parameter reference (`tissue-contact --print-parameters`): every entry
// of a scene with one subsection of each kind, and the count of entries
// without documentation, which must stay zero (each one is listed by its
// path if not).

#include "../tests.h"

#include <tissue_contact/scene/parameters.h>

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include <sstream>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

namespace
{
  /** Undo ParameterHandler's mangling of names in XML: every character
   * other than a letter or digit is written as '_' and two hex digits. */
  std::string
  demangle(const std::string &s)
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

  /** Count the entries below @p node (an entry has a "value" and a
   * "documentation" child) and collect the paths of those whose
   * documentation is empty. */
  void
  walk(const boost::property_tree::ptree &node,
       const std::string                 &path,
       unsigned int                      &n_entries,
       std::vector<std::string>          &undocumented)
  {
    for (const auto &[name, child] : node)
      {
        const std::string here =
          path.empty() ? demangle(name) : path + "/" + demangle(name);
        if (child.count("value") > 0 && child.count("documentation") > 0)
          {
            ++n_entries;
            if (child.get<std::string>("documentation")
                  .find_first_not_of(" \n\t") == std::string::npos)
              undocumented.push_back(here);
          }
        else
          walk(child, here, n_entries, undocumented);
      }
  }
} // namespace

int
main()
{
  initlog();

  std::ostringstream reference;
  Scene::SceneParameters::print_reference(reference);
  std::istringstream lines(reference.str());
  for (std::string line; std::getline(lines, line);)
    deallog << line << std::endl;

  Scene::SceneParameters p;
  p.resize(1, 1, 1, 1, 1);
  ParameterHandler prm;
  p.declare_parameters(prm);
  std::stringstream xml;
  prm.print_parameters(xml, ParameterHandler::XML);
  boost::property_tree::ptree tree;
  boost::property_tree::read_xml(xml, tree);

  unsigned int             n_entries = 0;
  std::vector<std::string> undocumented;
  walk(tree.get_child("ParameterHandler"), "", n_entries, undocumented);
  deallog << "entries: " << n_entries
          << ", without documentation: " << undocumented.size() << std::endl;
  for (const auto &u : undocumented)
    deallog << "  undocumented: " << u << std::endl;
}
