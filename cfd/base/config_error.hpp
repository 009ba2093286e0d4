#pragma once
// The project's one user-error type: bad case.yaml, inconsistent settings, a checkpoint that does not fit
// the case. It stops a run before any work with a message naming the key (or file), the value and what is
// allowed; `parcelflow` reports it once and exits with code 2. Internal invariants use PARCELFLOW_ASSERT
// (internal_error.hpp) instead: those are bugs.
#include <stdexcept>
#include <string>

namespace parcelflow::cfd {

class ConfigError : public std::runtime_error {
 public:
  explicit ConfigError(const std::string& message) : std::runtime_error(message) {}
  ConfigError(const std::string& key, const std::string& value, const std::string& allowed)
      : std::runtime_error(key + " = " + value + ": allowed is " + allowed) {}
};

}  // namespace parcelflow::cfd
