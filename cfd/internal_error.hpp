#pragma once
// Internal invariants: a failure is a bug in parcelflow, not a user error, so it is a different
// exception type (ConfigError is for the user's input).
#include <stdexcept>
#include <string>

namespace parcelflow::cfd {

class InternalError : public std::logic_error {
 public:
  explicit InternalError(const std::string& message) : std::logic_error(message) {}
};

}  // namespace parcelflow::cfd

#define PARCELFLOW_CFD_ASSERT(cond, msg)                                                         \
  do {                                                                                           \
    if (!(cond))                                                                                 \
      throw ::parcelflow::cfd::InternalError(std::string("internal error: ") + (msg) + " (" +    \
                                             #cond + ") at " + __FILE__ + ":" +                  \
                                             std::to_string(__LINE__));                          \
  } while (0)
