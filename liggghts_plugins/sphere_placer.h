// Random placement of spheres that must not overlap each other or a set of fixed spheres (plain C++, no
// LIGGGHTS; used by fix parcel/reinject). Candidate centres are drawn uniformly from a box shrunk by the
// radius; a candidate is free when the region test accepts it and it is at least r_i + r_j from every
// sphere added so far. `place` takes the first free candidate, `place_lowest` the free one with the
// smallest z of all its candidates. The random numbers come from std::mt19937_64 seeded by (seed, stream),
// so a placement is reproducible.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <random>
#include <unordered_map>
#include <vector>

namespace parcelflow::plugins {

using Point = std::array<double, 3>;

class SpherePlacer {
 public:
  // inside(centre, radius): whether a sphere there lies in the target region.
  using Inside = std::function<bool(const Point& centre, double radius)>;

  // lo/hi: the box candidates are drawn from; cell: edge of the search grid (about the largest diameter).
  SpherePlacer(const Point& lo, const Point& hi, double cell, Inside inside, std::uint32_t seed,
               std::uint64_t stream);

  void add(const Point& centre, double radius);
  // whether a sphere (centre, radius) overlaps a sphere added so far (touching is not overlapping)
  bool overlaps(const Point& centre, double radius) const;
  // Up to `attempts` candidates; on success writes the centre, adds the sphere and returns true.
  bool place(double radius, int attempts, Point& centre) { return choose(radius, attempts, false, centre); }
  // Draws all `attempts` candidates and takes the free one lowest in z (the same on success otherwise).
  bool place_lowest(double radius, int attempts, Point& centre) { return choose(radius, attempts, true, centre); }

 private:
  bool choose(double radius, int attempts, bool lowest, Point& centre);
  bool candidate(double radius, Point& p);  // draws one; whether it is free
  std::array<long, 3> cell_of(const Point& p) const;
  static std::uint64_t key(const std::array<long, 3>& c);

  Point lo_, hi_;
  double cell_;
  Inside inside_;
  std::mt19937_64 rng_;
  std::vector<Point> centres_;
  std::vector<double> radii_;
  double max_radius_ = 0.0;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> grid_;
};

}  // namespace parcelflow::plugins
