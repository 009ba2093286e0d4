#include "coupling/run/progress_line.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace parcelflow::coupling {

namespace {

std::string clock(double seconds) {
  if (!std::isfinite(seconds)) return "--:--:--";
  const long s = std::lround(seconds);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  return buf;
}

int percentOf(double part, double whole) { return whole > 0.0 ? static_cast<int>(std::lround(100.0 * part / whole)) : 0; }

// "DEM <value> | coupling <value> | gas <value> | output <value>", each value written by `value(phase)`
template <class Format>
std::string perPhase(Format value) {
  const char* const names[] = {"DEM", "coupling", "gas", "output"};
  std::string line;
  for (int p = 0; p < 4; ++p) line += std::string(p == 0 ? "" : " | ") + names[p] + " " + value(static_cast<Phase>(p));
  return line;
}

}  // namespace

std::string formatProgress(const ProgressState& s) {
  const double fraction = s.end_time > 0.0 ? s.time / s.end_time : 1.0;
  // the wall time counts from this run's start, so the ETA extrapolates this run's part only
  const double done = s.time - s.start_time, left = s.end_time - s.time;
  const double eta = done > 0.0 ? s.wall_seconds * std::max(left, 0.0) / done : INFINITY;
  const double rate = s.wall_seconds > 0.0 ? s.parcel_steps / s.wall_seconds : 0.0;
  const double busy = s.split.total();
  char buf[128];
  std::snprintf(buf, sizeof buf, "t = %.4f / %.4f s (%5.1f %%)  ETA %s  %.3g parcel-steps/s  ", s.time, s.end_time,
                100.0 * fraction, clock(eta).c_str(), rate);
  return buf + perPhase([&](Phase p) { return std::to_string(percentOf(s.split.seconds(p), busy)) + " %"; });
}

std::string formatSplitRange(const WallClockSplit& fastest, const WallClockSplit& slowest) {
  return perPhase([&](Phase p) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.1f-%.1f s", fastest.seconds(p), slowest.seconds(p));
    return std::string(buf);
  });
}

}  // namespace parcelflow::coupling
