// Size-class assignment of equal-mass parcels: every prefix of N parcels holds N f_k parcels of class k
// to within one parcel; the sequence is deterministic for a given seed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "liggghts_plugins/size_class_sequence.h"

using namespace parcelflow::plugins;

namespace {

std::vector<double> random_fractions(std::mt19937& rng, int K)
{
  std::uniform_real_distribution<double> u(0.01, 1.0);
  std::vector<double> f(K);
  double sum = 0;
  for (double& x : f) sum += (x = u(rng));
  for (double& x : f) x /= sum;
  return f;
}

}  // namespace

TEST(SizeClassSequence, EveryPrefixWithinOneParcelPerClass)
{
  std::mt19937 rng(4242);
  double worst = 0.0;
  long cases = 0;
  std::vector<std::vector<double>> distributions = {
      {1.0}, {0.5, 0.5}, {0.3, 0.7}, {1.0 / 3, 1.0 / 3, 1.0 / 3}, {0.05, 0.15, 0.3, 0.3, 0.15, 0.05},
      {0.001, 0.999}, {0.2, 0.2, 0.2, 0.2, 0.2}};
  for (int r = 0; r < 40; ++r) distributions.push_back(random_fractions(rng, 2 + r % 12));
  for (const auto& f : distributions)
    for (std::uint32_t seed : {1u, 12345679u, 86028157u, 4294967295u}) {
      SizeClassSequence seq(f, seed);
      std::vector<long> count(f.size(), 0);
      for (std::uint64_t n = 1; n <= 3000; ++n) {
        ++count[seq.class_of(n - 1)];
        for (std::size_t k = 0; k < f.size(); ++k) {
          const double dev = std::fabs(count[k] - static_cast<double>(n) * f[k]);
          worst = std::max(worst, dev);
          ASSERT_LT(dev, 1.0) << "n=" << n << " class " << k << " f=" << f[k] << " seed " << seed;
        }
      }
      ++cases;
    }
  std::printf("[ sequence ] %ld distributions x seeds, every prefix N <= 3000: max |count - N f| = %.6f parcels\n",
              cases, worst);
}

TEST(SizeClassSequence, DeterministicAndSeedOnlyOrdersTies)
{
  const std::vector<double> f = {0.25, 0.25, 0.25, 0.25};
  SizeClassSequence a(f, 12345679u), b(f, 12345679u), c(f, 86028157u);
  bool differs = false;
  for (std::uint64_t i = 0; i < 1000; ++i) {
    EXPECT_EQ(a.class_of(i), b.class_of(i));
    differs = differs || a.class_of(i) != c.class_of(i);
  }
  EXPECT_TRUE(differs) << "the seed should order classes with equal fractions";
  // random access in any order gives the same classes
  SizeClassSequence d(f, 12345679u);
  for (std::uint64_t i = 1000; i-- > 0;) EXPECT_EQ(d.class_of(i), a.class_of(i));
  const auto counts = a.counts(1000);
  for (auto n : counts) EXPECT_EQ(n, 250u);
}

TEST(SizeClassSequence, LargeN)
{
  const std::vector<double> f = {0.1, 0.2, 0.35, 0.3, 0.05};
  SizeClassSequence seq(f, 12345679u);
  for (std::uint64_t N : {1000ull, 12345ull, 100000ull, 520000ull}) {
    const auto c = seq.counts(N);
    for (std::size_t k = 0; k < f.size(); ++k) EXPECT_LT(std::fabs(c[k] - N * f[k]), 1.0) << "N=" << N << " k=" << k;
  }
}
