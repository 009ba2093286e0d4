// The progress line of a coupled run: simulated time, percent done, ETA, parcel-steps per second and the
// split of wall time between DEM, coupling and gas. Printed by rank 0 at a wall-clock interval.
#pragma once

#include <array>
#include <string>

namespace parcelflow::coupling {

enum class Phase { dem, coupling, gas, output };

class WallClockSplit {
 public:
  void add(Phase phase, double seconds) { seconds_[static_cast<int>(phase)] += seconds; }
  double seconds(Phase phase) const { return seconds_[static_cast<int>(phase)]; }
  double total() const { return seconds_[0] + seconds_[1] + seconds_[2] + seconds_[3]; }

 private:
  std::array<double, 4> seconds_{};
};

struct ProgressState {
  double time = 0.0;          // simulated time done [s]
  double start_time = 0.0;    // simulated time at which this run started (a checkpoint's, or 0) [s]
  double end_time = 0.0;      // simulated time to do [s]
  double wall_seconds = 0.0;  // since the coupled loop started
  double parcel_steps = 0.0;  // sum over DEM steps of the number of parcels
  WallClockSplit split;
};

// "t = 0.250 / 1.000 s (25.0 %)  ETA 0:01:30  2.31e+06 parcel-steps/s  DEM 55 % | coupling 10 % | gas 33 % | output 2 %"
std::string formatProgress(const ProgressState& s);

// Each phase's seconds on the fastest and the slowest rank, for the closing summary: a rank that waits for
// another shows the wait in the phase where they next meet, so a wide range points at a load imbalance.
// "DEM 83.1-84.0 s | coupling 19.2-20.5 s | gas 5.4-5.5 s | output 0.0-0.1 s"
std::string formatSplitRange(const WallClockSplit& fastest, const WallClockSplit& slowest);

}  // namespace parcelflow::coupling
