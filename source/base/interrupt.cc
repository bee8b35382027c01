#include <tissue_contact/base/interrupt.h>

#include <csignal>
#include <cstring>

namespace TissueContact
{
  namespace
  {
    volatile std::sig_atomic_t received = 0;

    extern "C" void
    on_signal(const int signal)
    {
      received = signal;
    }
  } // namespace


  Interrupted::Interrupted(const int signal, const std::string &where)
    : std::runtime_error(
        std::string("interrupted by ") +
        (signal == SIGINT  ? "SIGINT (Ctrl-C)" :
         signal == SIGTERM ? "SIGTERM" :
                             "signal " + std::to_string(signal)) +
        where)
    , signal(signal)
  {}


  void
  install_interrupt_handlers()
  {
    struct sigaction action;
    std::memset(&action, 0, sizeof(action));
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    // the first signal sets the flag, a second one acts as by default;
    // system calls interrupted by it are restarted
    action.sa_flags = SA_RESETHAND | SA_RESTART;
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
  }


  void
  check_interrupt()
  {
    if (received != 0)
      throw Interrupted(received);
  }
} // namespace TissueContact
