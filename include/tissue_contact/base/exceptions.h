#pragma once

#include <exception>
#include <string>

namespace TissueContact
{
  /**
   * The user-facing text of an exception on one line: for a deal.II
   * exception its "additional information" (the ExcMessage text, or the
   * ParameterHandler's description naming the file, line and entry), for
   * any other exception what(). Used wherever an error is reported to the
   * user or wrapped with more context.
   */
  std::string
  error_message(const std::exception &e);
} // namespace TissueContact
