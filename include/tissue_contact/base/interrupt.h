#pragma once

#include <stdexcept>
#include <string>

namespace TissueContact
{
  /**
   * Stopping a run on SIGINT (Ctrl-C) or SIGTERM without losing what it
   * wrote: install_interrupt_handlers() makes the first such signal only
   * set a flag (a second one ends the program at once, as by default);
   * the drivers call check_interrupt() between their steps, after any file
   * being written is complete, and it throws Interrupted. The program then
   * reports where the results are and exits with 128 + the signal number.
   */
  class Interrupted : public std::runtime_error
  {
  public:
    /** @p where: what was kept, appended to the message. */
    Interrupted(const int signal, const std::string &where = "");

    /** The signal received. */
    const int signal;
  };

  /** Catch SIGINT and SIGTERM as above. */
  void
  install_interrupt_handlers();

  /** Throw Interrupted if a signal was received since the handlers were
   * installed. */
  void
  check_interrupt();
} // namespace TissueContact
