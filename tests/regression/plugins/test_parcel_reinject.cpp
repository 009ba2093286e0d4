// fix parcel/reinject inside LIGGGHTS (1-3 ranks, the box split along z so that the outlet at the top and
// the return region at the bottom lie on different ranks): parcels rise into the outlet and are put back.
// At every step: parcels in the box + pending = the initial count, their mass + pending mass = the initial
// mass, cumulative out - in = pending. After every reinjection step: the parcels put back lie inside the
// return region and overlap no other parcel (periodic images included). At the end: the same IDs (atoms +
// pending), each with its own dp/np (fix parcel) and u_f (fix parcel/implicit_drag). Also: parcels pending
// in a crowded return region across write_restart / read_restart in a new instance, and the warning line;
// and a burst of 2,400 parcels put back in one step (more than LIGGGHTS' 1000 spare atom-map entries).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <set>

#include "domain.h"
#include "liggghts_plugins/fix_parcel.h"
#include "liggghts_plugins/fix_parcel_implicit_drag.h"
#include "liggghts_plugins/fix_parcel_reinject.h"
#include "tests/regression/plugins/liggghts_session.h"
#include "update.h"

using namespace parcelflow::plugins;
using namespace parcelflow::plugins::testing;

namespace {

const std::string kDir = PARCEL_TEST_DIR;
constexpr double kWidth = 0.02;  // periodic in x and y
constexpr int kEvery = 10;
constexpr long kParcels = 300;

struct Box {
  double lo[3], hi[3];
};
const Box kBottom = {{0, 0, 0.001}, {0.02, 0.02, 0.011}};            // region bottom (reinject_physics.in)
const Box kCell = {{0.0088, 0.0088, 0.002}, {0.0112, 0.0112, 0.006}};  // region cell: room for one parcel

using Values = std::array<double, 3>;  // dp, np, u_f,x
double dp_marker(int tag) { return 1e-3 * (1.0 + (tag % 89) / 100.0); }
double uf_marker(int tag) { return 0.01 * tag; }  // with kappa = 0 it does not act

std::map<int, Values> values_by_tag(Session& s)
{
  auto* p = s.fix<FixParcel>("p");
  auto* d = s.fix<FixParcelImplicitDrag>("drag");
  return gather_by_tag<3>(s.lmp(), [&](int i) {
    return Values{p->dp(i), p->np(i), d->peratom()[i][FixParcelImplicitDrag::UFX]};
  });
}

std::map<int, std::array<double, 1>> owners(Session& s)
{
  const double me = rank();
  return gather_by_tag<1>(s.lmp(), [&](int) { return std::array<double, 1>{me}; });
}

// the rank whose subdomain holds point p
int owner_of(Session& s, const double* p)
{
  const LAMMPS_NS::Domain* d = s.lmp()->domain;
  bool mine = true;
  for (int k = 0; k < 3; ++k) mine = mine && p[k] >= d->sublo[k] && p[k] < d->subhi[k];
  return static_cast<int>(max_all(mine ? rank() : -1.0));
}

void start(Session& s, const std::string& return_region, const std::string& options)
{
  s.cmd("variable D string " + kDir);
  s.cmd("variable N equal " + std::to_string(kParcels));
  s.file(kDir + "/reinject_box.in");
  s.cmd("fix re all parcel/reinject outlet top return " + return_region + " velocity 0 0 0.5 every " +
        std::to_string(kEvery) + " " + options);
}

// What must hold at every step, and the worst values met.
struct Balance {
  long n0 = 0;
  double m0 = 0.0;
  std::map<int, Values> initial;
  long count_errors = 0, counter_errors = 0, placed = 0, placed_on_other_rank = 0, outside = 0, max_pending = 0;
  double worst_mass = 0.0, min_gap = std::numeric_limits<double>::infinity();

  static double local_mass(Session& s)
  {
    double m = 0.0;
    for (int i = 0; i < s.lmp()->atom->nlocal; ++i) m += s.lmp()->atom->rmass[i];
    return sum_all(m);
  }

  // after the insertion: markers only the per-atom columns can carry, then the initial state
  void mark(Session& s)
  {
    LAMMPS_NS::Atom* atom = s.lmp()->atom;
    for (int i = 0; i < atom->nlocal; ++i) {
      s.fix<FixParcel>("p")->peratom()[i][FixParcel::DP] = dp_marker(atom->tag[i]);
      s.fix<FixParcelImplicitDrag>("drag")->peratom()[i][FixParcelImplicitDrag::UFX] = uf_marker(atom->tag[i]);
    }
    initial = values_by_tag(s);
    n0 = static_cast<long>(atom->natoms);
    m0 = local_mass(s);
  }

  void run(Session& s, int steps, const Box& ret)
  {
    for (int k = 0; k < steps; ++k) {
      const bool reinjection = (s.lmp()->update->ntimestep + 1) % kEvery == 0;
      std::map<int, std::array<double, 1>> before;
      if (reinjection) before = owners(s);
      s.cmd("run 1 pre no post no");
      check(s, ret, reinjection, before);
    }
  }

  void check(Session& s, const Box& ret, bool reinjection, const std::map<int, std::array<double, 1>>& before)
  {
    auto* re = s.fix<FixParcelReinject>("re");
    const long pending = static_cast<long>(re->counter(FixParcelReinject::PENDING_N));
    count_errors += static_cast<long>(s.lmp()->atom->natoms) + pending != n0;
    counter_errors += re->counter(FixParcelReinject::TOTAL_OUT_N) - re->counter(FixParcelReinject::TOTAL_IN_N) !=
                      pending;
    const double mass = local_mass(s) + re->counter(FixParcelReinject::PENDING_MASS);
    worst_mass = std::max(worst_mass, std::fabs(mass / m0 - 1.0));
    max_pending = std::max(max_pending, pending);
    if (!reinjection || re->placed_tags().empty()) return;
    LAMMPS_NS::Atom* atom = s.lmp()->atom;
    const auto spheres = gather_by_tag<4>(s.lmp(), [&](int i) {
      return std::array<double, 4>{atom->x[i][0], atom->x[i][1], atom->x[i][2], atom->radius[i]};
    });
    const auto now = owners(s);
    for (long tag : re->placed_tags()) {
      const auto& a = spheres.at(static_cast<int>(tag));
      ++placed;
      for (int k = 0; k < 3; ++k) outside += a[k] - a[3] < ret.lo[k] - 1e-15 || a[k] + a[3] > ret.hi[k] + 1e-15;
      const auto was = before.find(static_cast<int>(tag));
      placed_on_other_rank += was != before.end() && was->second[0] != now.at(static_cast<int>(tag))[0];
      for (const auto& [other, b] : spheres) {
        if (other == tag) continue;
        double d2 = 0.0;
        for (int k = 0; k < 3; ++k) {
          double d = a[k] - b[k];
          if (k < 2) d -= kWidth * std::round(d / kWidth);
          d2 += d * d;
        }
        min_gap = std::min(min_gap, std::sqrt(d2) - a[3] - b[3]);
      }
    }
  }

  // every initial ID once, as an atom or pending; atoms keep their values
  void check_ids(Session& s)
  {
    const auto now = values_by_tag(s);
    const auto pending = s.fix<FixParcelReinject>("re")->pending_tags();
    std::set<int> ids;
    long duplicates = 0, changed = 0;
    for (const auto& [tag, v] : now) {
      ids.insert(tag);
      changed += !initial.count(tag) || initial.at(tag) != v;
    }
    for (long tag : pending) duplicates += !ids.insert(static_cast<int>(tag)).second;
    duplicates += static_cast<long>(s.lmp()->atom->natoms) - static_cast<long>(now.size());
    long missing = 0;
    for (const auto& [tag, v] : initial) missing += !ids.count(tag);
    const long unknown = static_cast<long>(ids.size()) + missing - static_cast<long>(initial.size());
    PF_PRINT("[ reinject ] IDs: %zu atoms + %zu pending; %ld missing, %ld duplicated, %ld unknown; %ld atoms with "
             "changed dp/np/u_f\n", now.size(), pending.size(), missing, duplicates, unknown, changed);
    EXPECT_EQ(missing, 0);
    EXPECT_EQ(duplicates, 0);
    EXPECT_EQ(unknown, 0);
    EXPECT_EQ(changed, 0);
  }

  void expect_held(const char* what) const
  {
    PF_PRINT("[ reinject ] %s, %d ranks: steps with atoms + pending != %ld: %ld, with total out - in != pending: "
             "%ld; max |(M + M_pending)/M0 - 1| = %.2e; %ld parcels put back (%ld onto another rank), %ld sticking "
             "out of the return region, min gap to another parcel %.3e m; max pending %ld\n",
             what, nranks(), n0, count_errors, counter_errors, worst_mass, placed, placed_on_other_rank, outside,
             min_gap, max_pending);
    EXPECT_GT(n0, 250);
    EXPECT_EQ(count_errors, 0);
    EXPECT_EQ(counter_errors, 0);
    EXPECT_LT(worst_mass, 1e-12);
    EXPECT_EQ(outside, 0);
    EXPECT_GE(min_gap, -1e-12);
  }
};

}  // namespace

TEST(FixParcelReinject, MassAndIdsKeptAtEveryStep)
{
  Session s("none");
  start(s, "bottom", "seed 4711");
  s.cmd("run 1");  // inserts the parcels
  Balance b;
  b.mark(s);
  b.run(s, 6000, kBottom);
  b.expect_held("circulation through region bottom");
  auto* re = s.fix<FixParcelReinject>("re");
  EXPECT_GT(b.placed, 100);
  EXPECT_EQ(re->counter(FixParcelReinject::TOTAL_IN_N), static_cast<double>(b.placed));
  b.check_ids(s);
  const double outlet[3] = {0.01, 0.01, 0.095}, back[3] = {0.01, 0.01, 0.006};
  const int outlet_rank = owner_of(s, outlet), return_rank = owner_of(s, back);
  PF_PRINT("[ reinject ] outlet on rank %d, return region on rank %d\n", outlet_rank, return_rank);
  if (nranks() > 1) {
    EXPECT_NE(outlet_rank, return_rank);
    EXPECT_GT(b.placed_on_other_rank, 0);
  }
}

TEST(FixParcelReinject, PendingParcelsSurviveRestart)
{
  const std::string dir = scratch_dir("reinject");
  Balance b;
  std::vector<long> pending;
  double totals[4];
  const FixParcelReinject::Entry kTotals[4] = {FixParcelReinject::TOTAL_OUT_N, FixParcelReinject::TOTAL_OUT_MASS,
                                               FixParcelReinject::TOTAL_IN_N, FixParcelReinject::TOTAL_IN_MASS};
  {
    Session s(dir + "/log.before");
    start(s, "cell", "seed 4711 attempts 5");
    s.cmd("run 1");
    b.mark(s);
    b.run(s, 2000, kCell);
    b.expect_held("crowded region cell");
    auto* re = s.fix<FixParcelReinject>("re");
    pending = re->pending_tags();
    for (int k = 0; k < 4; ++k) totals[k] = re->counter(kTotals[k]);
    EXPECT_GT(pending.size(), 10u);
    EXPECT_GT(b.placed, 0);
    s.cmd("write_restart " + dir + "/pending.restart");
  }
  if (rank() == 0) {  // the warning line was shown while it happened
    std::ifstream log(dir + "/log.before");
    std::string line, found;
    while (std::getline(log, line) && found.empty())
      if (line.find("pending: no free position in region cell within 5 attempts") != std::string::npos) found = line;
    std::printf("[ reinject ] first warning in the log: %s\n", found.c_str());
    EXPECT_FALSE(found.empty());
  }
  {
    Session s(dir + "/log.after");
    s.cmd("variable D string " + kDir);
    s.cmd("variable F string " + dir + "/pending.restart");
    s.file(kDir + "/reinject_restart.in");
    s.cmd("fix re all parcel/reinject outlet top return cell velocity 0 0 0.5 every " + std::to_string(kEvery) +
          " seed 4711 attempts 5");
    s.cmd("run 0");
    auto* re = s.fix<FixParcelReinject>("re");
    long differ = re->pending_tags() != pending;
    for (int k = 0; k < 4; ++k) differ += re->counter(kTotals[k]) != totals[k];
    PF_PRINT("[ reinject ] after read_restart: %zu pending (before %zu), cumulative out %.0f in %.0f, values that "
             "differ %ld\n", re->pending_tags().size(), pending.size(), re->counter(FixParcelReinject::TOTAL_OUT_N),
             re->counter(FixParcelReinject::TOTAL_IN_N), differ);
    EXPECT_EQ(differ, 0);
    b.check(s, kCell, false, {});
    b.run(s, 1500, kCell);
    b.expect_held("after the restart");
    const auto atoms = values_by_tag(s);
    long back = 0;
    for (long tag : pending) back += atoms.count(static_cast<int>(tag));
    PF_PRINT("[ reinject ] parcels pending at the restart now back in the box: %ld of %zu\n", back, pending.size());
    EXPECT_GT(back, 0);
    EXPECT_GT(re->counter(FixParcelReinject::TOTAL_IN_N), totals[2]);
    b.check_ids(s);
  }
  remove_scratch_dir(dir);
}

// All 2,400 parcels leave in one step and are created again at once: LIGGGHTS' atom map (sized for the
// atoms of its last map_init plus 1000) must be re-sized, or the exchange's map_clear overruns it (heap
// corruption: "free(): invalid next size" in Atom::map_set, seen with the 67,500-parcel FCC bed).
TEST(FixParcelReinject, BurstLargerThanTheAtomMapsSpareRoom)
{
  constexpr long kBurst = 2400;
  Session s("none");
  s.cmd("variable N equal " + std::to_string(kBurst));
  s.file(kDir + "/reinject_burst.in");
  s.cmd("run 1");  // inserts the parcels
  ASSERT_EQ(static_cast<long>(s.lmp()->atom->natoms), kBurst);
  s.cmd("run 19 pre no post no");  // the reinjection step 10, and steps after it that rebuild the map again
  auto* re = s.fix<FixParcelReinject>("re");
  LAMMPS_NS::Atom* atom = s.lmp()->atom;
  long upper = 0, unmapped = 0;
  for (int i = 0; i < atom->nlocal; ++i) {
    upper += atom->x[i][2] > 0.1;
    const int j = atom->map(atom->tag[i]);
    unmapped += j < 0 || atom->tag[j] != atom->tag[i];
  }
  upper = static_cast<long>(sum_all(static_cast<double>(upper)));
  unmapped = static_cast<long>(sum_all(static_cast<double>(unmapped)));
  PF_PRINT("[ reinject ] burst, %d ranks: %.0f out and %.0f in at once, %.0f atoms (%ld in the upper half), %.0f "
           "pending, %ld local atoms not found through the atom map\n",
           nranks(), re->counter(FixParcelReinject::TOTAL_OUT_N), re->counter(FixParcelReinject::TOTAL_IN_N),
           static_cast<double>(atom->natoms), upper, re->counter(FixParcelReinject::PENDING_N), unmapped);
  EXPECT_EQ(re->counter(FixParcelReinject::TOTAL_IN_N), static_cast<double>(kBurst));
  EXPECT_EQ(upper, kBurst);
  EXPECT_EQ(static_cast<long>(atom->natoms), kBurst);
  EXPECT_EQ(unmapped, 0);
}
