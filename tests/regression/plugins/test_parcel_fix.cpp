// fix parcel inside LIGGGHTS (in-process, 1-3 MPI ranks): dp/np of inserted parcels, parcel mass,
// attachment of dp/np to the right atoms under migration between ranks, dump columns, the size
// distribution assignment, the restart round trip (write_restart, clear, read_restart), and dp_by_type
// (two size classes of one parcel diameter kept as atom types; per-type-pair linear scaling).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "atom.h"
#include "liggghts_plugins/fix_parcel.h"
#include "liggghts_plugins/fix_parcel_implicit_drag.h"
#include "fix_property_global.h"
#include "tests/regression/plugins/liggghts_session.h"
#include "liggghts_plugins/size_class_sequence.h"
#include "update.h"

using namespace parcelflow::plugins;
using namespace parcelflow::plugins::testing;

namespace {

const std::string kDir = PARCEL_TEST_DIR;

// Box + N parcels of radius R inserted with random velocities by the next run.
void setup_box(Session& s, double R, const std::string& parcel_args)
{
  s.cmd("variable R equal " + std::to_string(R));
  s.file(kDir + "/box_setup.in");
  s.cmd("fix p all parcel " + parcel_args);
}

void insert(Session& s, int index, int n, long seed)
{
  s.cmd("variable I equal " + std::to_string(index));
  s.cmd("variable N equal " + std::to_string(n));
  s.cmd("variable S equal " + std::to_string(seed));
  s.file(kDir + "/insert.in");
}

double tag_function(int tag) { return 1e-3 * (1.0 + (tag % 97) / 100.0); }

// marker values for the drag fix's columns: a negligible kappa (M/kappa ~ 1e8 s) and u_f = f(tag)
std::array<double, 4> drag_marker(int tag) { return {1e-12 * (1 + tag % 7), 1.0 * tag, -1.0 * tag, 0.5 * tag}; }

// Two atom types of parcels (D = 4 mm, density 2500) holding 1 mm and 2 mm particles; type 3 is the walls.
const std::string kByType = "mode constant_diameter diameter 0.004 dp_by_type 0.001 0.002 none";
constexpr double kByTypeDp[2] = {0.001, 0.002}, kByTypeNp[2] = {64.0, 8.0};

void setup_two_types(Session& s, const std::string& parcel_args)
{
  s.cmd("variable R equal 0.002");
  s.cmd("variable rho2 equal 2500");
  s.file(kDir + "/two_types_box.in");
  s.file(kDir + "/two_types_setup.in");
  s.cmd("fix p all parcel " + parcel_args);
}

// Parcels per type and the largest relative deviations of dp, np and LIGGGHTS' mass from dp_by_type's
// dp, (D/dp)^3 and np m_p, over all ranks.
struct ByTypeCheck {
  long count[2] = {0, 0};
  double dp = 0, np = 0, mass = 0;
};

ByTypeCheck check_by_type(Session& s)
{
  auto* fp = s.fix<FixParcel>("p");
  LAMMPS_NS::Atom* atom = s.lmp()->atom;
  ByTypeCheck c;
  for (int i = 0; i < atom->nlocal; ++i) {
    const int t = atom->type[i] - 1;
    ++c.count[t];
    c.dp = std::max(c.dp, std::fabs(fp->dp(i) / kByTypeDp[t] - 1.0));
    c.np = std::max(c.np, std::fabs(fp->np(i) / kByTypeNp[t] - 1.0));
    const double m_p = atom->density[i] * M_PI / 6.0 * std::pow(fp->dp(i), 3);
    c.mass = std::max(c.mass, std::fabs(atom->rmass[i] / (fp->np(i) * m_p) - 1.0));
  }
  for (long& n : c.count) n = sum_all(n);
  c.dp = max_all(c.dp);
  c.np = max_all(c.np);
  c.mass = max_all(c.mass);
  return c;
}

// owner rank of every atom, by tag
std::map<int, std::array<double, 1>> owners(Session& s)
{
  const double me = rank();
  return gather_by_tag<1>(s.lmp(), [&](int) { return std::array<double, 1>{me}; });
}

}  // namespace

TEST(FixParcel, ConstantNpMassAndMigration)
{
  const std::string dir = scratch_dir("migration");
  Session s(dir + "/log.migration");
  setup_box(s, 0.002, "mode constant_np np 8");
  s.cmd("unfix integr");
  s.cmd("fix drag all parcel/implicit_drag");  // the coupled integrator: its per-atom data must migrate too
  insert(s, 1, 150, 32452843);
  s.cmd("run 1");
  auto* fp = s.fix<FixParcel>("p");
  ASSERT_NE(fp, nullptr);
  LAMMPS_NS::Atom* atom = s.lmp()->atom;
  const long natoms = static_cast<long>(atom->natoms);  // insert/pack may place a few less than asked
  ASSERT_GT(natoms, 100);

  // dp from the inserted diameter and np; LIGGGHTS' mass (density = particle density) = np m_p
  double worst_dp = 0, worst_mass = 0;
  for (int i = 0; i < atom->nlocal; ++i) {
    EXPECT_EQ(fp->np(i), 8.0);
    worst_dp = std::max(worst_dp, std::fabs(fp->dp(i) / 0.002 - 1.0));
    const double m_p = atom->density[i] * M_PI / 6.0 * std::pow(fp->dp(i), 3);
    worst_mass = std::max(worst_mass, std::fabs(atom->rmass[i] / (fp->np(i) * m_p) - 1.0));
  }
  worst_dp = max_all(worst_dp);
  worst_mass = max_all(worst_mass);
  PF_PRINT("[ parcel ] constant_np np 8, D 4 mm: max |dp/2mm - 1| = %.2e, max |m/(np m_p) - 1| = %.2e\n", worst_dp,
           worst_mass);
  EXPECT_LT(worst_dp, 1e-14);
  EXPECT_LT(worst_mass, 1e-12);

  // dp (and the drag fix's kappa, u_f) as known functions of the tag, then thousands of steps with atoms
  // crossing rank boundaries
  auto* drag = s.fix<FixParcelImplicitDrag>("drag");
  ASSERT_NE(drag, nullptr);
  for (int i = 0; i < atom->nlocal; ++i) {
    fp->peratom()[i][FixParcel::DP] = tag_function(atom->tag[i]);
    const auto m = drag_marker(atom->tag[i]);
    drag->peratom()[i][FixParcelImplicitDrag::KAPPA] = m[0];
    for (int k = 0; k < 3; ++k) drag->peratom()[i][FixParcelImplicitDrag::UFX + k] = m[1 + k];
  }
  const auto owner_before = owners(s);
  const long received_before = sum_all(fp->atoms_received());
  s.cmd("run 1000");
  for (int c = 0; c < 4; ++c) s.cmd("run 500 pre no post no");  // the coupling loop's way of running
  fp = s.fix<FixParcel>("p");
  const long received = sum_all(fp->atoms_received()) - received_before;
  const auto owner_after = owners(s);
  long moved = 0;
  for (const auto& [tag, r] : owner_after) moved += owner_before.at(tag)[0] != r[0];
  const auto values = gather_by_tag<2>(s.lmp(), [&](int i) { return std::array<double, 2>{fp->dp(i), fp->np(i)}; });
  ASSERT_EQ(static_cast<long>(values.size()), natoms);
  long wrong = 0;
  for (const auto& [tag, v] : values) wrong += v[0] != tag_function(tag) || v[1] != 8.0;
  drag = s.fix<FixParcelImplicitDrag>("drag");
  const auto drag_values = gather_by_tag<4>(s.lmp(), [&](int i) {
    const double* d = drag->peratom()[i];
    return std::array<double, 4>{d[FixParcelImplicitDrag::KAPPA], d[FixParcelImplicitDrag::UFX],
                                 d[FixParcelImplicitDrag::UFY], d[FixParcelImplicitDrag::UFZ]};
  });
  long wrong_drag = 0;
  for (const auto& [tag, v] : drag_values) wrong_drag += v != drag_marker(tag);
  PF_PRINT("[ parcel ] %d ranks, 3000 steps: atoms received from other ranks %ld, atoms now on another rank "
           "%ld of %ld, atoms with wrong dp/np %ld, with wrong kappa/u_f (parcel/implicit_drag) %ld\n", nranks(),
           received, moved, natoms, wrong, wrong_drag);
  EXPECT_EQ(wrong, 0);
  EXPECT_EQ(wrong_drag, 0);
  if (nranks() > 1) {
    EXPECT_GT(received, 0);
    EXPECT_GT(moved, 0);
  }

  // restart round trip of values that only the restart file can know (dp = f(tag), not derivable)
  s.cmd("write_restart " + dir + "/np8.restart");
  s.clear();
  s.cmd("variable F string " + dir + "/np8.restart");
  s.cmd("variable R equal 0.002");
  s.file(kDir + "/restart_continue.in");
  s.cmd("fix p all parcel mode constant_np np 8");
  s.cmd("unfix integr");
  s.cmd("fix drag all parcel/implicit_drag");
  s.cmd("run 0");
  fp = s.fix<FixParcel>("p");
  drag = s.fix<FixParcelImplicitDrag>("drag");
  const auto drag_restored = gather_by_tag<4>(s.lmp(), [&](int i) {
    const double* d = drag->peratom()[i];
    return std::array<double, 4>{d[FixParcelImplicitDrag::KAPPA], d[FixParcelImplicitDrag::UFX],
                                 d[FixParcelImplicitDrag::UFY], d[FixParcelImplicitDrag::UFZ]};
  });
  long differ_drag = 0;
  for (const auto& [tag, v] : drag_values) differ_drag += !drag_restored.count(tag) || drag_restored.at(tag) != v;
  const auto restored = gather_by_tag<2>(s.lmp(), [&](int i) { return std::array<double, 2>{fp->dp(i), fp->np(i)}; });
  long differ = 0;
  for (const auto& [tag, v] : values) differ += !restored.count(tag) || restored.at(tag) != v;
  PF_PRINT("[ parcel ] restart round trip of dp = f(tag): %zu parcels read back, %ld differ; kappa/u_f of "
           "parcel/implicit_drag: %ld differ\n", restored.size(), differ, differ_drag);
  EXPECT_EQ(differ_drag, 0);
  EXPECT_EQ(static_cast<long>(restored.size()), natoms);
  EXPECT_EQ(differ, 0);
  remove_scratch_dir(dir);
}

TEST(FixParcel, DistributionDumpAndRestart)
{
  const std::string dir = scratch_dir("restart");
  const std::vector<double> d = {0.001, 0.0015, 0.002}, f = {0.2, 0.3, 0.5};
  const std::string args = "mode constant_diameter diameter 0.004 distribution 0.001 0.2 0.0015 0.3 0.002 0.5 "
                           "seed 86028157";
  std::map<int, std::array<double, 2>> before;
  double assigned_before = 0;
  {
    Session s(dir + "/log.before");
    setup_box(s, 0.002, args);
    insert(s, 1, 120, 32452843);
    // more inserted in the middle of the run (step 300; particles_in_region counts those already there):
    // their size classes are set in pre_force of that step
    s.cmd("fix ins2 all insert/pack seed 49979687 distributiontemplate pdd vel uniform 0 0 0 1 1 1 "
          "insert_every once start 300 overlapcheck yes all_in yes particles_in_region 150 region ins");
    s.cmd("run 299");
    LAMMPS_NS::Atom* atom = s.lmp()->atom;
    const long n0 = static_cast<long>(atom->natoms);
    s.cmd("run 701");
    auto* fp = s.fix<FixParcel>("p");
    const long n1 = static_cast<long>(atom->natoms);
    ASSERT_GT(n1, 120);
    EXPECT_EQ(fp->parcels_assigned(), static_cast<double>(n1));
    before = gather_by_tag<2>(s.lmp(), [&](int i) { return std::array<double, 2>{fp->dp(i), fp->np(i)}; });

    // the parcels, numbered by tag, follow the class sequence; counts within one parcel of N f_k
    SizeClassSequence seq(f, 86028157u);
    std::vector<long> count(3, 0);
    long index = 0, wrong = 0;
    for (const auto& [tag, v] : before) {
      const int c = seq.class_of(index++);
      ++count[c];
      wrong += v[0] != d[c] || std::fabs(v[1] / std::pow(0.004 / d[c], 3) - 1.0) > 1e-14;
    }
    PF_PRINT("[ parcel ] distribution 1/1.5/2 mm with fractions 0.2/0.3/0.5, %ld parcels (%ld inserted at step 1, the rest at "
             "step 300): counts %ld/%ld/%ld (N f = %.1f/%.1f/%.1f), parcels off the sequence %ld\n",
             n1, n0, count[0], count[1], count[2], n1 * f[0], n1 * f[1], n1 * f[2], wrong);
    EXPECT_EQ(wrong, 0);
    for (int k = 0; k < 3; ++k) EXPECT_LT(std::fabs(count[k] - n1 * f[k]), 1.0);

    // dump custom with the fix columns
    s.cmd("dump dp all custom 1 " + dir + "/parcels.dump id f_p[1] f_p[2]");
    s.cmd("dump_modify dp sort id");
    s.cmd("run 0");
    s.cmd("undump dp");
    if (rank() == 0) {
      std::ifstream in(dir + "/parcels.dump");
      std::string line;
      while (std::getline(in, line) && line.rfind("ITEM: ATOMS", 0) != 0) {}
      long rows = 0, bad = 0;
      int tag;
      double dp, np;
      while (in >> tag >> dp >> np) {
        ++rows;
        bad += std::fabs(dp / before.at(tag)[0] - 1) > 1e-5 || std::fabs(np / before.at(tag)[1] - 1) > 1e-5;
      }
      std::printf("[ parcel ] dump custom id f_p[1] f_p[2]: %ld rows, %ld differing from dp/np\n", rows, bad);
      EXPECT_EQ(rows, n1);
      EXPECT_EQ(bad, 0);
    }
    before = gather_by_tag<2>(s.lmp(), [&](int i) { return std::array<double, 2>{fp->dp(i), fp->np(i)}; });
    assigned_before = fp->parcels_assigned();
    s.cmd("write_restart " + dir + "/parcels.restart");

    // restart round trip in the same instance: clear, register again, read_restart
    s.clear();
    s.cmd("variable F string " + dir + "/parcels.restart");
    s.cmd("variable R equal 0.002");
    s.file(kDir + "/restart_continue.in");
    s.cmd("fix p all parcel " + args);
    s.cmd("run 0");
    fp = s.fix<FixParcel>("p");
    ASSERT_NE(fp, nullptr);
    const auto after = gather_by_tag<2>(s.lmp(), [&](int i) { return std::array<double, 2>{fp->dp(i), fp->np(i)}; });
    long differ = 0;
    for (const auto& [tag, v] : before) differ += !after.count(tag) || after.at(tag) != v;
    PF_PRINT("[ parcel ] restart round trip: %zu parcels read back, %ld with different dp/np; parcels numbered "
             "before %.0f, after %.0f\n", after.size(), differ, assigned_before, fp->parcels_assigned());
    EXPECT_EQ(static_cast<long>(after.size()), n1);
    EXPECT_EQ(differ, 0);
    EXPECT_EQ(fp->parcels_assigned(), assigned_before);

    // the sequence continues after the restart: still within one parcel per class
    insert(s, 3, n1 + 40, 67867967);
    s.cmd("run 200");
    const auto all = gather_by_tag<2>(s.lmp(), [&](int i) { return std::array<double, 2>{fp->dp(i), fp->np(i)}; });
    std::vector<long> c2(3, 0);
    for (const auto& [tag, v] : all)
      for (int k = 0; k < 3; ++k) c2[k] += v[0] == d[k];
    const double N = static_cast<double>(all.size());
    PF_PRINT("[ parcel ] after restart + insertion: %zu parcels, counts %ld/%ld/%ld (N f = %.1f/%.1f/%.1f)\n",
             all.size(), c2[0], c2[1], c2[2], N * f[0], N * f[1], N * f[2]);
    EXPECT_GT(static_cast<long>(all.size()), n1);
    for (int k = 0; k < 3; ++k) EXPECT_LT(std::fabs(c2[k] - N * f[k]), 1.0);
  }
  remove_scratch_dir(dir);
}

TEST(FixParcel, DiameterByTypeKeepsClassesAsTypes)
{
  const std::string dir = scratch_dir("by_type");
  Session s(dir + "/log.by_type");
  setup_two_types(s, kByType);
  insert(s, 1, 150, 32452843);
  s.cmd("run 300");
  const long natoms = static_cast<long>(s.lmp()->atom->natoms);
  ByTypeCheck c = check_by_type(s);
  PF_PRINT("[ parcel ] dp_by_type 1/2 mm, D 4 mm: %ld + %ld parcels of types 1 + 2 (%ld atoms); max relative "
           "deviation of dp %.2e, np %.2e (64, 8), mass from np m_p %.2e\n", c.count[0], c.count[1], natoms, c.dp,
           c.np, c.mass);
  EXPECT_EQ(c.count[0] + c.count[1], natoms);
  EXPECT_GT(c.count[0], natoms / 4);  // 50/50 by mass of equal masses; LIGGGHTS draws the types
  EXPECT_GT(c.count[1], natoms / 4);
  EXPECT_EQ(c.dp, 0.0);
  EXPECT_LT(c.np, 1e-14);
  EXPECT_LT(c.mass, 1e-12);

  // restart round trip (the fix's restart state holds the diameters per type), then more parcels
  auto* fp = s.fix<FixParcel>("p");
  const auto before = gather_by_tag<3>(s.lmp(), [&](int i) {
    return std::array<double, 3>{fp->dp(i), fp->np(i), double(s.lmp()->atom->type[i])};
  });
  s.cmd("write_restart " + dir + "/by_type.restart");
  s.clear();
  s.cmd("variable R equal 0.002");
  s.cmd("variable rho2 equal 2500");
  s.cmd("read_restart " + dir + "/by_type.restart");
  s.file(kDir + "/two_types_setup.in");
  s.cmd("fix p all parcel " + kByType);
  s.cmd("run 0");
  fp = s.fix<FixParcel>("p");
  const auto after = gather_by_tag<3>(s.lmp(), [&](int i) {
    return std::array<double, 3>{fp->dp(i), fp->np(i), double(s.lmp()->atom->type[i])};
  });
  long differ = 0;
  for (const auto& [tag, v] : before) differ += !after.count(tag) || after.at(tag) != v;
  insert(s, 2, natoms + 60, 67867967);
  s.cmd("run 200");
  c = check_by_type(s);
  const long n2 = static_cast<long>(s.lmp()->atom->natoms);
  PF_PRINT("[ parcel ] dp_by_type restart round trip: %zu parcels read back, %ld with different dp/np/type; "
           "after inserting more: %ld + %ld parcels, max deviation dp %.2e, np %.2e, mass %.2e\n", after.size(),
           differ, c.count[0], c.count[1], c.dp, c.np, c.mass);
  EXPECT_EQ(static_cast<long>(after.size()), natoms);
  EXPECT_EQ(differ, 0);
  EXPECT_GT(n2, natoms);
  EXPECT_EQ(c.count[0] + c.count[1], n2);
  EXPECT_EQ(c.dp, 0.0);
  EXPECT_LT(c.np, 1e-14);
  EXPECT_LT(c.mass, 1e-12);
  remove_scratch_dir(dir);
}

TEST(FixParcel, DiameterByTypeScalesEachTypePair)
{
  Session s("none");
  s.cmd("variable R equal 0.002");
  s.cmd("variable rho2 equal 2500");
  s.file(kDir + "/two_types_box.in");
  s.file(kDir + "/two_types_setup.in");
  const std::vector<std::string> names = {"kn", "kt", "gn", "gt"};
  std::map<std::string, std::array<double, 9>> original;
  for (const std::string& name : names)
    for (int k = 0; k < 9; ++k) original[name][k] = s.fix<LAMMPS_NS::FixPropertyGlobal>(name)->compute_array(k / 3, k % 3);
  s.cmd("fix p all parcel " + kByType + " scaling linear");
  // l of each pair: D/dp = 4 and 2 for a type with itself and with the walls, ((64 + 8)/2)^(1/3) = 36^(1/3)
  // for types 1-2, 1 for walls-walls; kn, kt x l, gamman, gammat (mass-specific) / l
  const double l12 = std::cbrt(36.0);
  const std::array<double, 9> l = {4.0, l12, 4.0, l12, 2.0, 2.0, 4.0, 2.0, 1.0};
  double worst = 0;
  for (const std::string& name : names)
    for (int k = 0; k < 9; ++k) {
      const double expected = original[name][k] * (name[0] == 'k' ? l[k] : 1.0 / l[k]);
      const double got = s.fix<LAMMPS_NS::FixPropertyGlobal>(name)->compute_array(k / 3, k % 3);
      worst = std::max(worst, std::fabs(got / expected - 1.0));
    }
  PF_PRINT("[ parcel ] dp_by_type scaling linear: l 1-1 4, 1-2 %.6f, 2-2 2, walls 4 / 2 / 1; kn, kt, gamman, gammat "
           "of all 9 pairs: max relative deviation from original x l (k) or / l (gamma) %.2e; gamman 1-2 %g -> %g\n",
           l12, worst, original["gn"][1], s.fix<LAMMPS_NS::FixPropertyGlobal>("gn")->compute_array(0, 1));
  EXPECT_LT(worst, 1e-15);
  // parcels of one density run (the fix checks it at every run's start)
  insert(s, 1, 60, 32452843);
  s.cmd("run 10");
  s.cmd("run 10");
  EXPECT_GT(s.lmp()->atom->natoms, 30);
}
