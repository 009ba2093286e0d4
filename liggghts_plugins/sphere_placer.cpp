#include "liggghts_plugins/sphere_placer.h"

#include <cmath>

namespace parcelflow::plugins {
namespace {

constexpr long kOffset = 1L << 20;  // cell indices relative to lo_ fit in 21 bits each

// uniform in [0, 1) from the top 53 bits (exact and the same on every platform)
double unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

std::mt19937_64 seeded(std::uint32_t seed, std::uint64_t stream)
{
  std::seed_seq seq{seed, static_cast<std::uint32_t>(stream), static_cast<std::uint32_t>(stream >> 32)};
  return std::mt19937_64(seq);
}

}  // namespace

SpherePlacer::SpherePlacer(const Point& lo, const Point& hi, double cell, Inside inside, std::uint32_t seed,
                           std::uint64_t stream)
    : lo_(lo), hi_(hi), cell_(cell), inside_(std::move(inside)), rng_(seeded(seed, stream))
{
}

std::array<long, 3> SpherePlacer::cell_of(const Point& p) const
{
  std::array<long, 3> c;
  for (int k = 0; k < 3; ++k) c[k] = static_cast<long>(std::floor((p[k] - lo_[k]) / cell_));
  return c;
}

std::uint64_t SpherePlacer::key(const std::array<long, 3>& c)
{
  std::uint64_t k = 0;
  for (long v : c) k = (k << 21) | (static_cast<std::uint64_t>(v + kOffset) & ((1u << 21) - 1));
  return k;
}

void SpherePlacer::add(const Point& centre, double radius)
{
  grid_[key(cell_of(centre))].push_back(centres_.size());
  centres_.push_back(centre);
  radii_.push_back(radius);
  max_radius_ = std::max(max_radius_, radius);
}

bool SpherePlacer::overlaps(const Point& centre, double radius) const
{
  const long reach = static_cast<long>(std::ceil((radius + max_radius_) / cell_));
  const auto c = cell_of(centre);
  for (long i = c[0] - reach; i <= c[0] + reach; ++i)
    for (long j = c[1] - reach; j <= c[1] + reach; ++j)
      for (long k = c[2] - reach; k <= c[2] + reach; ++k) {
        const auto it = grid_.find(key({i, j, k}));
        if (it == grid_.end()) continue;
        for (std::size_t n : it->second) {
          double d2 = 0.0;
          for (int a = 0; a < 3; ++a) d2 += (centre[a] - centres_[n][a]) * (centre[a] - centres_[n][a]);
          const double contact = radius + radii_[n];
          if (d2 < contact * contact) return true;
        }
      }
  return false;
}

bool SpherePlacer::candidate(double radius, Point& p)
{
  // a sphere inside the region has its centre at least `radius` inside the box
  for (int k = 0; k < 3; ++k) p[k] = lo_[k] + radius + unit(rng_) * (hi_[k] - lo_[k] - 2.0 * radius);
  return inside_(p, radius) && !overlaps(p, radius);
}

bool SpherePlacer::choose(double radius, int attempts, bool lowest, Point& centre)
{
  for (int k = 0; k < 3; ++k)
    if (hi_[k] - lo_[k] < 2.0 * radius) return false;
  bool found = false;
  for (int a = 0; a < attempts && (lowest || !found); ++a) {
    Point p;
    if (!candidate(radius, p) || (found && p[2] >= centre[2])) continue;
    centre = p;
    found = true;
  }
  if (found) add(centre, radius);
  return found;
}

}  // namespace parcelflow::plugins
