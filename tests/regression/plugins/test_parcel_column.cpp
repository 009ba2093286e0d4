// Dry settled column: the same box filled with real particles (dp = 2 mm, np = 1) and with parcels
// (np = 8 and 27, D = 4 and 6 mm, same total mass, `scaling linear`) settles to the same bed height.
// Bed height H = M / (rho_p A phi_bulk): the height of the bed at the solid fraction phi_bulk measured in
// the bed's interior (a slab 9-20 mm above the floor, at least 1.5 D from floor and surface; exact
// sphere-slab volumes). It compares the packing that coarse graining controls; the floor and surface
// layers, whose thickness scales with D, are excluded. H2 = 2 * (mass-weighted mean centre height) is
// printed as well: it includes the looser packing next to the floor, a wall effect of order D.
#include <gtest/gtest.h>

#include <cmath>

#include "liggghts_plugins/fix_parcel.h"
#include "tests/regression/plugins/liggghts_session.h"

using namespace parcelflow::plugins;
using namespace parcelflow::plugins::testing;

namespace {

const std::string kDir = PARCEL_TEST_DIR;
constexpr double kDp = 0.002, kArea = 0.036 * 0.036, kRho = 2500.0;

constexpr double kSlabLo = 0.009, kSlabHi = 0.020;

struct Bed {
  long n;
  double mass, height, centroid_height, mean_speed, solid_fraction;
};

// volume of a sphere (centre z, radius r) between the planes lo and hi
double slab_volume(double z, double r, double lo, double hi)
{
  const double t1 = std::max(lo - z, -r), t2 = std::min(hi - z, r);
  if (t2 <= t1) return 0.0;
  auto F = [r](double t) { return M_PI * (r * r * t - t * t * t / 3.0); };
  return F(t2) - F(t1);
}

Bed settle(int np, long n)
{
  const double D = kDp * std::cbrt(static_cast<double>(np));
  Session s("none");
  s.cmd("variable R equal " + std::to_string(0.5 * D));
  s.cmd("variable N equal " + std::to_string(n));
  s.cmd("variable skin equal " + std::to_string(0.25 * D));
  s.file(kDir + "/column.in");
  s.file(kDir + "/column_materials.in");
  s.cmd("fix p all parcel mode constant_np np " + std::to_string(np) + " scaling linear");
  s.file(kDir + "/column_run.in");
  s.cmd("run 15000");
  LAMMPS_NS::Atom* atom = s.lmp()->atom;
  const auto v = gather_by_tag<3>(s.lmp(), [&](int i) {
    const double* u = atom->v[i];
    return std::array<double, 3>{atom->rmass[i], atom->x[i][2], std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2])};
  });
  Bed b{static_cast<long>(v.size()), 0, 0, 0, 0, 0};
  double mz = 0, slab_solid = 0;
  for (const auto& [tag, a] : v) {
    b.mass += a[0];
    mz += a[0] * a[1];
    b.mean_speed += a[2] / v.size();
    slab_solid += slab_volume(a[1], 0.5 * D, kSlabLo, kSlabHi);
  }
  b.centroid_height = 2.0 * mz / b.mass;
  b.solid_fraction = slab_solid / (kArea * (kSlabHi - kSlabLo));
  b.height = b.mass / kRho / (kArea * b.solid_fraction);
  return b;
}

}  // namespace

TEST(ParcelColumn, SameBedHeightForParticlesAndParcels)
{
  const long n1 = 5400;  // 5400 = 8 * 675 = 27 * 200: the same solid mass in all three beds
  std::vector<std::pair<int, Bed>> beds;
  for (int np : {1, 8, 27}) beds.emplace_back(np, settle(np, n1 / np));
  const Bed& ref = beds[0].second;
  for (const auto& [np, b] : beds) {
    const double err = b.height / ref.height - 1.0;
    const double err2 = b.centroid_height / ref.centroid_height - 1.0;
    PF_PRINT("[ column ] np %2d (D = %.1f mm): %ld parcels, mass %.6g kg, bulk solid fraction %.4f, bed height "
             "M/(rho A phi) = %.3f mm (%+.2f %% vs np=1), 2<z> = %.3f mm (%+.2f %% vs np=1), mean speed %.2e m/s\n",
             np, 1e3 * kDp * std::cbrt(np), b.n, b.mass, b.solid_fraction, 1e3 * b.height, 100 * err,
             1e3 * b.centroid_height, 100 * err2, b.mean_speed);
    EXPECT_LT(std::fabs(err), 0.03);
    EXPECT_NEAR(b.mass / ref.mass, 1.0, 1e-12);  // insert/pack placed all parcels: the same solid mass
    EXPECT_LT(b.mean_speed, 0.01);                      // settled
  }
}
