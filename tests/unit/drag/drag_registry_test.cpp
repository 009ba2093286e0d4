// Run-time selection by name and the batched per-parcel loop (limits counted, never silent).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "tests/unit/drag/drag_test_context.hpp"
#include "coupling/drag/parcel_drag.hpp"
#include "cfd/base/config_error.hpp"
#include "cfd/base/internal_error.hpp"

using namespace parcelflow::coupling;

TEST(DragRegistry, AllNamesConstructAndRoundTrip) {
  const std::vector<std::string> names = dragLawNames();
  EXPECT_EQ(names, (std::vector<std::string>{"WenYu", "Gidaspow", "GidaspowBlend", "Ergun", "DiFelice",
                                              "BeetstraVanDerHoefKuipers", "RadlSundaresanFilteredBVK"}));
  for (const std::string& n : names) {
    const DragLaw law = makeDragLaw(n, test::fccContext());
    EXPECT_EQ(dragLawName(law), n);
    EXPECT_FALSE(dragLawReference(law).empty());
  }
}

TEST(DragRegistry, UnknownNameListsValidNames) {
  try {
    makeDragLaw("wenyu");  // names are case-sensitive
    FAIL() << "no exception";
  } catch (const parcelflow::cfd::ConfigError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("wenyu"), std::string::npos) << msg;
    for (const std::string& n : dragLawNames()) EXPECT_NE(msg.find(n), std::string::npos) << msg;
  }
}

namespace {
struct Batch {
  std::vector<double> alphaG, slip, dp, np, dMean;
  ParcelDragBatch view(bool withMean) const {
    ParcelDragBatch b;
    b.size = alphaG.size();
    b.alphaG = alphaG.data();
    b.slip = slip.data();
    b.dp = dp.data();
    b.np = np.data();
    b.dMean = withMean ? dMean.data() : nullptr;
    b.rhoG = 1.2;
    b.muG = 1.8e-5;
    return b;
  }
};
}  // namespace

TEST(ParcelDrag, BatchLoopEqualsSingleEvaluationsForEveryLaw) {
  Batch b;
  for (int p = 0; p < 200; ++p) {
    b.alphaG.push_back(0.36 + 0.64 * p / 199.0);
    b.slip.push_back(1e-3 * (p % 17) * (p % 5));
    b.dp.push_back(1e-4 * (1 + p % 7));
    b.np.push_back(1.0 + 50.0 * (p % 3));
    b.dMean.push_back(4e-4);
  }
  const DragLimits limits{0.2};
  for (const std::string& name : dragLawNames()) {
    const DragLaw law = makeDragLaw(name, test::fccContext());
    std::vector<double> kappa(b.alphaG.size());
    const DragStats st = computeParcelKappa(law, b.view(true), limits, kappa.data());
    EXPECT_EQ(st.parcels, 200u);
    EXPECT_EQ(st.alphaGFloored + st.alphaGAboveOne + st.invalidInput, 0u);
    // the filtered law bounds its correction where phi > 0.6 (a_g < 0.4: 13 of these parcels), and says so
    std::size_t beyondFit = 0;
    for (double a : b.alphaG) beyondFit += RadlSundaresanDrag::largeFilterCorrection(1.0 - a) < 0.0;
    EXPECT_EQ(beyondFit, 13u);
    EXPECT_EQ(st.filterCorrectionClamped, name == "RadlSundaresanFilteredBVK" ? beyondFit : 0u) << name;
    for (std::size_t p = 0; p < kappa.size(); ++p) {
      DragInput in{b.alphaG[p], 1.2, 1.8e-5, b.dp[p], b.slip[p], b.dMean[p]};
      const double want = parcelKappa(b.np[p], b.dp[p], exchangeCoefficientPerSolidVolume(law, in));
      EXPECT_EQ(kappa[p], want) << name << " parcel " << p;
    }
  }
}

TEST(ParcelDrag, FloorAndOutOfRangeAreCountedNotSilent) {
  Batch b;
  b.alphaG = {0.1, 0.25, 1.0 + 1e-12, std::numeric_limits<double>::quiet_NaN(), 0.5, 0.5};
  b.slip = {0.1, 0.1, 0.1, 0.1, -1.0, 0.1};
  b.dp = {1e-4, 1e-4, 1e-4, 1e-4, 1e-4, 0.0};
  b.np = {1, 1, 1, 1, 1, 1};
  const DragLaw law = makeDragLaw("WenYu");
  std::vector<double> kappa(6, -1.0);
  const DragStats st = computeParcelKappa(law, b.view(false), DragLimits{0.2}, kappa.data());
  EXPECT_EQ(st.alphaGFloored, 1u);
  EXPECT_EQ(st.alphaGAboveOne, 1u);
  EXPECT_EQ(st.invalidInput, 3u);  // NaN a_g, negative slip, zero diameter
  EXPECT_DOUBLE_EQ(st.minAlphaG, 0.1);
  DragInput floored{0.2, 1.2, 1.8e-5, 1e-4, 0.1, 0.0};
  EXPECT_EQ(kappa[0], parcelKappa(1, 1e-4, exchangeCoefficientPerSolidVolume(law, floored)));
  EXPECT_TRUE(std::isfinite(kappa[2]) && kappa[2] > 0.0);
  EXPECT_EQ(kappa[3], 0.0);
  EXPECT_EQ(kappa[4], 0.0);
  EXPECT_EQ(kappa[5], 0.0);
}

TEST(ParcelDrag, RejectsMissingFloorAndGasProperties) {
  Batch b;
  b.alphaG = {0.5};
  b.slip = {0.1};
  b.dp = {1e-4};
  b.np = {1};
  std::vector<double> kappa(1);
  const DragLaw law = makeDragLaw("DiFelice");
  EXPECT_THROW(computeParcelKappa(law, b.view(false), DragLimits{}, kappa.data()), parcelflow::cfd::InternalError);
  EXPECT_THROW(computeParcelKappa(law, b.view(false), DragLimits{1.0}, kappa.data()), parcelflow::cfd::InternalError);
  ParcelDragBatch v = b.view(false);
  v.muG = 0.0;
  EXPECT_THROW(computeParcelKappa(law, v, DragLimits{0.3}, kappa.data()), parcelflow::cfd::InternalError);
}
