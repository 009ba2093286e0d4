#include "liggghts_plugins/size_class_sequence.h"

#include <random>
#include <stdexcept>

namespace parcelflow::plugins {

SizeClassSequence::SizeClassSequence(std::vector<double> mass_fractions, std::uint32_t seed)
    : fractions_(std::move(mass_fractions)), tie_rank_(fractions_.size()), count_(fractions_.size(), 0)
{
  if (fractions_.empty() || fractions_.size() > 65535)
    throw std::invalid_argument("SizeClassSequence: needs 1 to 65535 classes");
  std::vector<int> order(fractions_.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  std::mt19937 rng(seed);
  for (std::size_t k = order.size(); k > 1; --k) {   // Fisher-Yates with explicit modulo
    const std::size_t j = rng() % k;
    std::swap(order[k - 1], order[j]);
  }
  for (std::size_t r = 0; r < order.size(); ++r) tie_rank_[order[r]] = static_cast<int>(r);
}

void SizeClassSequence::extend_to(std::uint64_t n)
{
  const std::size_t K = fractions_.size();
  while (sequence_.size() < n) {
    const double next = static_cast<double>(sequence_.size() + 1);
    std::size_t best = 0;
    double best_deficit = 0.0;
    for (std::size_t k = 0; k < K; ++k) {
      const double deficit = next * fractions_[k] - static_cast<double>(count_[k]);
      const double tol = 1e-12 * next;
      if (k == 0 || deficit > best_deficit + tol ||
          (deficit >= best_deficit - tol && tie_rank_[k] < tie_rank_[best])) {
        best = k;
        best_deficit = deficit;
      }
    }
    ++count_[best];
    sequence_.push_back(static_cast<std::uint16_t>(best));
  }
}

int SizeClassSequence::class_of(std::uint64_t index)
{
  extend_to(index + 1);
  return sequence_[index];
}

std::vector<std::uint64_t> SizeClassSequence::counts(std::uint64_t n)
{
  extend_to(n);
  std::vector<std::uint64_t> c(fractions_.size(), 0);
  for (std::uint64_t i = 0; i < n; ++i) ++c[sequence_[i]];
  return c;
}

}  // namespace parcelflow::plugins
