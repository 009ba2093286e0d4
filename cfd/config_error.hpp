#pragma once
// User errors (bad case.yaml, inconsistent settings) are ConfigError: they stop a run before any work
// with a message naming the key path, the value and what is allowed. Internal invariants use
// PARCELFLOW_CFD_ASSERT (internal_error.hpp) instead.
#include <stdexcept>
#include <string>

namespace parcelflow::cfd {

class ConfigError : public std::runtime_error {
 public:
  explicit ConfigError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace parcelflow::cfd
