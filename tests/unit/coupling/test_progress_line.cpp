// The progress line's ETA extrapolates the wall time of this run over the simulated time this run has done:
// a run continued from a checkpoint at 45 s that took 60 s of wall time for 1 s has 4 s, 240 s, left.
#include <gtest/gtest.h>

#include "coupling/run/progress_line.h"

using namespace parcelflow::coupling;

namespace {
ProgressState state(double start, double time, double end, double wall) {
  ProgressState s;
  s.start_time = start;
  s.time = time;
  s.end_time = end;
  s.wall_seconds = wall;
  return s;
}
}  // namespace

TEST(ProgressLine, EtaOfAFreshRun) {
  const std::string line = formatProgress(state(0.0, 0.25, 1.0, 30.0));
  EXPECT_NE(line.find("( 25.0 %)"), std::string::npos) << line;
  EXPECT_NE(line.find("ETA 0:01:30"), std::string::npos) << line;
}

TEST(ProgressLine, EtaOfARunContinuedFromACheckpointCountsOnlyThisRunsPart) {
  const std::string line = formatProgress(state(45.0, 46.0, 50.0, 60.0));
  EXPECT_NE(line.find("( 92.0 %)"), std::string::npos) << line;
  EXPECT_NE(line.find("ETA 0:04:00"), std::string::npos) << line;
}

TEST(ProgressLine, NoEtaBeforeAnyStep) {
  EXPECT_NE(formatProgress(state(45.0, 45.0, 50.0, 0.0)).find("ETA --:--:--"), std::string::npos);
}

TEST(ProgressLine, SplitRangeNamesEachPhaseWithItsFastestAndSlowestRank) {
  WallClockSplit fastest, slowest;
  fastest.add(Phase::dem, 83.14);
  slowest.add(Phase::dem, 84.0);
  fastest.add(Phase::coupling, 19.2);
  slowest.add(Phase::coupling, 20.46);
  fastest.add(Phase::gas, 5.4);
  slowest.add(Phase::gas, 5.5);
  slowest.add(Phase::output, 0.08);
  EXPECT_EQ(formatSplitRange(fastest, slowest),
            "DEM 83.1-84.0 s | coupling 19.2-20.5 s | gas 5.4-5.5 s | output 0.0-0.1 s");
}

TEST(ProgressLine, WholeLineWithTheSplitOfEachPhase) {
  ProgressState s = state(0.0, 0.25, 1.0, 30.0);
  s.parcel_steps = 6.93e7;
  s.split.add(Phase::dem, 55.0);
  s.split.add(Phase::coupling, 10.0);
  s.split.add(Phase::gas, 33.0);
  s.split.add(Phase::output, 2.0);
  EXPECT_EQ(formatProgress(s), "t = 0.2500 / 1.0000 s ( 25.0 %)  ETA 0:01:30  2.31e+06 parcel-steps/s  "
                               "DEM 55 % | coupling 10 % | gas 33 % | output 2 %");
}
