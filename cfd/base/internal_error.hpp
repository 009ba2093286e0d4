#pragma once
// The project's one internal-invariant check: a failure is a bug in parcelflow, not a user error, so it is
// a different exception type (ConfigError is for the user's input). `parcelflow` reports it as a bug on the
// rank that found it and stops all ranks.
#include <stdexcept>
#include <string>

namespace parcelflow::cfd {

class InternalError : public std::logic_error {
 public:
  explicit InternalError(const std::string& message) : std::logic_error(message) {}
};

}  // namespace parcelflow::cfd

#define PARCELFLOW_ASSERT(cond, msg)                                                             \
  do {                                                                                           \
    if (!(cond))                                                                                 \
      throw ::parcelflow::cfd::InternalError(std::string("internal error: ") + (msg) + " (" +    \
                                             #cond + ") at " + __FILE__ + ":" +                  \
                                             std::to_string(__LINE__));                          \
  } while (0)
