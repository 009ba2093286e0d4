// The per-parcel conductance H = np Nu k_g pi d_p over a batch: independent values, np scaling (a parcel
// heats exactly as each of its particles), and every limit counted.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "coupling/heat/parcel_heat_transfer.hpp"

using namespace parcelflow::coupling;

namespace {

ParcelHeatBatch batchOf(const std::vector<double>& a, const std::vector<double>& slip, const std::vector<double>& dp,
                        const std::vector<double>& np) {
  ParcelHeatBatch b;
  b.size = a.size();
  b.alphaG = a.data();
  b.slip = slip.data();
  b.dp = dp.data();
  b.np = np.data();
  b.gas.rho = 1.2;
  b.gas.mu = 1.8e-5;
  b.gas.conductivity = 0.026;
  b.gas.heatCapacity = 1005.0;
  return b;
}

constexpr double kPi = 3.14159265358979323846;

}  // namespace

TEST(ParcelHeatTransfer, ConductanceMatchesIndependentValue) {
  // python3: a, slip, d, np = 0.4, 0.5, 5e-4, 8; Re = a*1.2*slip*d/1.8e-5; Pr = 1005*1.8e-5/0.026
  //          Nu = gunn(a, Re, Pr) = 9.1238504323482239; h = Nu*0.026/d; H = np*h*pi*d*d = 0.0029809958350345924
  const std::vector<double> a{0.4}, slip{0.5}, dp{5e-4}, np{8.0};
  std::vector<double> h(1);
  const HeatStats s = computeParcelConductance(makeNusseltCorrelation("Gunn"), batchOf(a, slip, dp, np), {0.3}, h.data());
  EXPECT_NEAR(h[0], 0.0029809958350345924, 1e-14);
  EXPECT_EQ(s.parcels, 1u);
  EXPECT_EQ(s.outsideRange, 0u);
}

TEST(ParcelHeatTransfer, ParcelResponseTimeIsItsParticlesForAnyNp) {
  // H/np is one particle's h pi d^2, and the parcel's mass is np m_p: M c / H does not depend on np.
  const std::vector<double> a(3, 0.5), slip(3, 0.7), dp(3, 3e-4), np{1.0, 8.0, 27.0};
  std::vector<double> h(3);
  computeParcelConductance(makeNusseltCorrelation("RanzMarshall"), batchOf(a, slip, dp, np), {0.3}, h.data());
  EXPECT_NEAR(h[1] / 8.0, h[0], 1e-15 * h[0]);
  EXPECT_NEAR(h[2] / 27.0, h[0], 1e-15 * h[0]);
  // still gas, dilute: H = np 2 k pi d (Nu = 2)
  const std::vector<double> one{1.0}, still{0.0}, d{1e-3}, n{8.0};
  std::vector<double> h2(1);
  computeParcelConductance(makeNusseltCorrelation("Gunn"), batchOf(one, still, d, n), {0.3}, h2.data());
  EXPECT_NEAR(h2[0], 8.0 * 2.0 * 0.026 * kPi * 1e-3, 1e-16);
}

TEST(ParcelHeatTransfer, LimitsAreCounted) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // 0: floored (0.1 < 0.3); 1: above one; 2: invalid slip; 3: invalid dp; 4: Re = 1.2 * 1e3 * 2e-3 / 1.8e-5
  // = 1.33e5 > 1e5 (Gunn's range); 5: a_g 0.32 is above the floor but below Gunn's 0.35; 6: fine.
  const std::vector<double> a{0.1, 1.2, 0.5, 0.5, 1.0, 0.32, 0.5}, slip{0.1, 0.1, nan, 0.1, 1e3, 0.1, -0.0},
      dp{5e-4, 5e-4, 5e-4, 0.0, 2e-3, 5e-4, 5e-4}, np(7, 1.0);
  std::vector<double> h(7, -1.0);
  const HeatStats s = computeParcelConductance(makeNusseltCorrelation("Gunn"), batchOf(a, slip, dp, np), {0.3}, h.data());
  EXPECT_EQ(s.parcels, 7u);
  EXPECT_EQ(s.alphaGFloored, 1u);
  EXPECT_EQ(s.alphaGAboveOne, 1u);
  EXPECT_EQ(s.invalidInput, 2u);
  EXPECT_EQ(s.outsideRange, 3u);  // the floored one (evaluated at 0.3 < 0.35), Re > 1e5, a_g 0.32
  EXPECT_EQ(h[2], 0.0);
  EXPECT_EQ(h[3], 0.0);
  EXPECT_NEAR(s.maxReynolds, 1.2 * 1e3 * 2e-3 / 1.8e-5, 1e-9);
  // the floored parcel is evaluated at the floor, the one above one at 1
  const std::vector<double> af{0.3, 1.0}, sf{0.1, 0.1}, df(2, 5e-4), nf(2, 1.0);
  std::vector<double> hf(2);
  computeParcelConductance(makeNusseltCorrelation("Gunn"), batchOf(af, sf, df, nf), {0.3}, hf.data());
  EXPECT_EQ(h[0], hf[0]);
  EXPECT_EQ(h[1], hf[1]);
}
