#pragma once

#include <deal.II/base/timer.h>

#include <memory>
#include <string>

namespace TissueContact
{
  using namespace dealii;

  /**
   * A scope of the section @p name of @p timer, or nothing if @p timer is
   * null (not timed): `const auto scope = time_section(timer, "assembly");`
   * The sections of a run are listed in doc/users/running.md.
   */
  inline std::unique_ptr<TimerOutput::Scope>
  time_section(TimerOutput *timer, const std::string &name)
  {
    return timer != nullptr ?
             std::make_unique<TimerOutput::Scope>(*timer, name) :
             std::unique_ptr<TimerOutput::Scope>();
  }
} // namespace TissueContact
