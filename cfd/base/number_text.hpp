// Numbers in messages and in files parcelflow reads back.
#pragma once

#include <cstdio>
#include <string>

namespace parcelflow::cfd {

// six significant digits, as a user wrote them ("0.0002", "1e+300")
inline std::string shortNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// every digit a double holds: reads back to the same value
inline std::string exactNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// a printf pattern of up to four numbers (%g, %.3g, ...; unused ones are 0), for messages
inline std::string formatNumbers(const char* pattern, double a, double b = 0.0, double c = 0.0, double d = 0.0) {
  char buf[512];
  std::snprintf(buf, sizeof buf, pattern, a, b, c, d);
  return buf;
}

}  // namespace parcelflow::cfd
