#include <tissue_contact/base/exceptions.h>

#include <deal.II/base/exceptions.h>

#include <sstream>

namespace TissueContact
{
  std::string
  error_message(const std::exception &e)
  {
    std::string text;
    if (const auto *d = dynamic_cast<const dealii::ExceptionBase *>(&e))
      {
        std::ostringstream s;
        d->print_info(s);
        text = s.str();
        if (text.find_first_not_of(" \n") == std::string::npos)
          text = d->get_exc_name();
      }
    else
      text = e.what();
    // fold to one line with single spaces
    std::string line;
    bool        space = false;
    for (const char c : text)
      if (c == '\n' || c == ' ' || c == '\t')
        space = !line.empty();
      else
        {
          if (space)
            line += ' ';
          line += c;
          space = false;
        }
    return line;
  }
} // namespace TissueContact
