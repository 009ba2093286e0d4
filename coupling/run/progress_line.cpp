#include "progress_line.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

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

}  // namespace

std::string formatProgress(const ProgressState& s) {
  const double fraction = s.end_time > 0.0 ? s.time / s.end_time : 1.0;
  // the wall time counts from this run's start, so the ETA extrapolates this run's part only
  const double done = s.time - s.start_time, left = s.end_time - s.time;
  const double eta = done > 0.0 ? s.wall_seconds * std::max(left, 0.0) / done : INFINITY;
  const double rate = s.wall_seconds > 0.0 ? s.parcel_steps / s.wall_seconds : 0.0;
  const double busy = s.split.total();
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "t = %.4f / %.4f s (%5.1f %%)  ETA %s  %.3g parcel-steps/s  DEM %d %% | coupling %d %% | gas %d %% | "
                "output %d %%",
                s.time, s.end_time, 100.0 * fraction, clock(eta).c_str(), rate, percentOf(s.split.seconds(Phase::dem), busy),
                percentOf(s.split.seconds(Phase::coupling), busy), percentOf(s.split.seconds(Phase::gas), busy),
                percentOf(s.split.seconds(Phase::output), busy));
  return buf;
}

std::string formatSplitRange(const WallClockSplit& fastest, const WallClockSplit& slowest) {
  const char* const names[] = {"DEM", "coupling", "gas", "output"};
  std::string line;
  for (int p = 0; p < 4; ++p) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%s%s %.1f-%.1f s", p == 0 ? "" : " | ", names[p],
                  fastest.seconds(static_cast<Phase>(p)), slowest.seconds(static_cast<Phase>(p)));
    line += buf;
  }
  return line;
}

}  // namespace parcelflow::coupling
