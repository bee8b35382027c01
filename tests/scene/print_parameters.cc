// The parameter reference (`tissue-contact --print-parameters`): every entry
// of a scene with one subsection of each kind, and the count of entries
// without documentation, which must stay zero (each one is listed by its
// path if not). The JSON form holds as many entries, and the Markdown form
// is doc/users/parameters.md exactly: the page is regenerated with
// `tissue-contact --print-parameters=markdown > doc/users/parameters.md`,
// and this test fails when someone forgets.

#include "../tests.h"

#include <tissue_contact/base/parameter_tools.h>
#include <tissue_contact/scene/parameters.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include <fstream>
#include <sstream>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

namespace
{
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
        const std::string here = path.empty() ?
                                   demangle_xml_name(name) :
                                   path + "/" + demangle_xml_name(name);
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

  // JSON: the same entries
  std::stringstream json;
  Scene::SceneParameters::print_reference(json, "json");
  boost::property_tree::ptree json_tree;
  boost::property_tree::read_json(json, json_tree);
  unsigned int             n_json = 0;
  std::vector<std::string> json_undocumented;
  walk(json_tree, "", n_json, json_undocumented);
  deallog << "JSON entries: " << n_json << std::endl;

  // Markdown: the page in doc/users, compared line by line
  std::ostringstream markdown;
  Scene::SceneParameters::print_reference(markdown, "markdown");
  const std::string source = __FILE__;
  const std::string page =
    source.substr(0, source.rfind("tests/scene/")) + "doc/users/parameters.md";
  std::ifstream      file(page);
  const bool         found = file.is_open();
  std::ostringstream stored;
  stored << file.rdbuf();
  std::istringstream a(markdown.str()), b(stored.str());
  std::string        la, lb;
  unsigned int       line = 0, tables = 0;
  bool               same = found;
  while (same)
    {
      const bool more_a = static_cast<bool>(std::getline(a, la));
      const bool more_b = static_cast<bool>(std::getline(b, lb));
      ++line;
      if (!more_a && !more_b)
        break;
      if (more_a != more_b || la != lb)
        {
          same = false;
          deallog << "doc/users/parameters.md differs from the program's "
                     "reference at line "
                  << line << ":\n  page:    " << lb << "\n  program: " << la
                  << std::endl;
        }
      tables += la.rfind("## ", 0) == 0;
    }
  if (!found)
    deallog << "doc/users/parameters.md is missing" << std::endl;
  deallog << "doc/users/parameters.md is up to date: " << (same ? "yes" : "no")
          << " (" << tables << " subsections)" << std::endl;
}
