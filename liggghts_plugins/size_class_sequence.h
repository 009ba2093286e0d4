// Deterministic assignment of size classes to equal-mass parcels.
//
// With a constant parcel diameter every parcel has the same mass, so the number fraction of parcels in a
// class equals its mass fraction. The sequence gives parcel number n (0, 1, 2, ...) the class with the
// largest deficit (n+1) f_k - c_k(n) (c_k(n) = parcels of class k among the first n). Every prefix of
// N parcels then holds N f_k parcels of class k to within one parcel. Classes with equal deficit are
// ordered by a permutation drawn from the seed (mt19937, own Fisher-Yates: the same on every platform
// and every rank), so the sequence depends only on the fractions and the seed.
#pragma once

#include <cstdint>
#include <vector>

namespace parcelflow::plugins {

class SizeClassSequence {
 public:
  SizeClassSequence(std::vector<double> mass_fractions, std::uint32_t seed);

  // Class of parcel number `index` (0-based). Extends an internal cache: O(K) per new index.
  int class_of(std::uint64_t index);

  // Parcels per class among the first n of the sequence.
  std::vector<std::uint64_t> counts(std::uint64_t n);

  std::size_t size() const { return fractions_.size(); }

 private:
  void extend_to(std::uint64_t n);
  std::vector<double> fractions_;
  std::vector<int> tie_rank_;             // smaller rank wins a tie
  std::vector<std::uint64_t> count_;      // counts among the cached prefix
  std::vector<std::uint16_t> sequence_;   // cached classes
};

}  // namespace parcelflow::plugins
