// SpherePlacer (fix parcel/reinject's placement): placed spheres lie in the region and overlap neither the
// obstacles nor each other, touching is allowed, a full region gives up after the given attempts, and the
// same (seed, stream) gives the same positions; `place_lowest` takes the lowest free candidate.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "liggghts_plugins/sphere_placer.h"

using namespace parcelflow::plugins;

namespace {

const Point kLo = {0, 0, 0}, kHi = {0.01, 0.01, 0.02};

bool in_box(const Point& c, double r)
{
  for (int k = 0; k < 3; ++k)
    if (c[k] - r < kLo[k] || c[k] + r > kHi[k]) return false;
  return true;
}

double distance(const Point& a, const Point& b)
{
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

}  // namespace

TEST(SpherePlacer, NoOverlapInsideTheRegion)
{
  SpherePlacer placer(kLo, kHi, 0.002, in_box, 4711, 10);
  std::vector<Point> centres = {{0.005, 0.005, 0.01}};
  std::vector<double> radii = {0.003};
  placer.add(centres[0], radii[0]);
  for (int n = 0; n < 60; ++n) {
    const double r = n % 2 ? 0.001 : 0.0005;
    Point c;
    if (!placer.place(r, 200, c)) continue;
    centres.push_back(c);
    radii.push_back(r);
  }
  double min_gap = 1.0;
  long outside = 0;
  for (std::size_t i = 1; i < centres.size(); ++i) {
    outside += !in_box(centres[i], radii[i]);
    for (std::size_t j = 0; j < i; ++j) min_gap = std::min(min_gap, distance(centres[i], centres[j]) - radii[i] - radii[j]);
  }
  std::cout << "[ placer ] " << centres.size() - 1 << " of 60 spheres placed, min gap " << min_gap << " m, "
            << outside << " outside\n";
  EXPECT_GT(centres.size(), 40u);
  EXPECT_GE(min_gap, 0.0);
  EXPECT_EQ(outside, 0);
}

TEST(SpherePlacer, TouchingIsNotOverlapping)
{
  SpherePlacer placer({0, 0, 0}, {4, 4, 4}, 2.0, [](const Point&, double) { return true; }, 1, 0);
  placer.add({1, 1, 1}, 0.5);  // binary-exact values: the distances below are exact
  EXPECT_FALSE(placer.overlaps({1, 1, 2.25}, 0.75));  // distance 1.25 = r_i + r_j
  EXPECT_TRUE(placer.overlaps({1, 1, 2.25}, 0.7500001));
  EXPECT_TRUE(placer.overlaps({1.5, 1.5, 1.5}, 0.5));   // distance 0.87 < 1
  EXPECT_FALSE(placer.overlaps({3, 3, 3}, 0.5));
}

TEST(SpherePlacer, FullRegionGivesUpAndSameSeedSamePositions)
{
  // a region with room for one sphere: the second cannot be placed, however many attempts
  SpherePlacer tight({0, 0, 0}, {0.0021, 0.0021, 0.0021}, 0.002,
                     [](const Point& c, double r) { return c[0] - r >= 0 && c[0] + r <= 0.0021; }, 4711, 3);
  Point c;
  EXPECT_TRUE(tight.place(0.001, 100, c));
  EXPECT_FALSE(tight.place(0.001, 1000, c));
  EXPECT_FALSE(tight.place(0.002, 1000, c));  // larger than the box: refused without drawing

  std::vector<Point> runs[3];
  const std::uint64_t streams[3] = {42, 42, 43};
  for (int k = 0; k < 3; ++k) {
    SpherePlacer placer(kLo, kHi, 0.002, in_box, 4711, streams[k]);
    for (int n = 0; n < 10; ++n)
      if (placer.place(0.001, 50, c)) runs[k].push_back(c);
  }
  EXPECT_EQ(runs[0], runs[1]);
  EXPECT_NE(runs[0], runs[2]);
}

TEST(SpherePlacer, LowestTakesTheLowestFreeCandidate)
{
  // A tall box whose lower half is filled by a lattice of obstacles touching each other: the lowest free
  // position lies just above the lattice, and of the same candidates `place` takes the first free one.
  const Point lo{0, 0, 0}, hi{0.01, 0.01, 0.04};
  auto anywhere = [](const Point&, double) { return true; };
  SpherePlacer lowest(lo, hi, 0.002, anywhere, 99, 7), first(lo, hi, 0.002, anywhere, 99, 7);
  for (int i = 0; i <= 5; ++i)
    for (int j = 0; j <= 5; ++j)
      for (int k = 0; k <= 10; ++k) {
        lowest.add({0.002 * i, 0.002 * j, 0.002 * k}, 0.001);
        first.add({0.002 * i, 0.002 * j, 0.002 * k}, 0.001);
      }
  Point a, b;
  ASSERT_TRUE(lowest.place_lowest(0.001, 400, a));
  ASSERT_TRUE(first.place(0.001, 400, b));
  // free positions start in the hollows of the top obstacle layer (z 0.02), sqrt(2) radii above it; above
  // z 0.022 every position is free, so of 400 uniform candidates (4 % of the height each 1.5 mm) the
  // lowest free one lies below 0.0235 (the chance of none there is e^-16)
  EXPECT_GE(a[2], 0.02 + std::sqrt(2.0) * 0.001);
  EXPECT_LT(a[2], 0.0235);
  EXPECT_GT(b[2], a[2]);    // the first free candidate is almost surely higher
  EXPECT_TRUE(lowest.overlaps(a, 0.001));  // the placed sphere is added
  Point none;
  SpherePlacer full({0, 0, 0}, {0.0021, 0.0021, 0.0021}, 0.002, anywhere, 1, 1);
  full.add({0.00105, 0.00105, 0.00105}, 0.001);
  EXPECT_FALSE(full.place_lowest(0.001, 100, none));
}
