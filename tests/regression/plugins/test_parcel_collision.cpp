// Two parcels colliding head-on (no gravity) with `scaling linear`, l = 1, 2, 4 (np = 1, 8, 64):
// the measured restitution coefficient equals the particle-level one and the contact duration grows
// in proportion to l. Both damping conventions of hooke/stiffness (mass-specific gamman and
// absolute_damping on with gamman_abs) are checked. With dp_by_type (two particle sizes in parcels of one
// diameter) the contact of the two types and that of a type with the wall keep the restitution of the
// particle pair and last l times as long, l of the pair's rule. With shear_stress E the parcel-parcel
// restitution is 1 - e'^2 = l^4 (1 - E^2) and the wall contacts keep theirs.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "liggghts_plugins/fix_parcel.h"
#include "tests/regression/plugins/liggghts_session.h"
#include "liggghts_plugins/parcel_math.h"
#include "update.h"

using namespace parcelflow::plugins;
using namespace parcelflow::plugins::testing;

namespace {

const std::string kDir = PARCEL_TEST_DIR;
constexpr double kDp = 0.002, kRho = 2500.0, kKn = 1000.0, kTargetE = 0.7;

struct Collision {
  double e;         // measured restitution coefficient
  long steps;       // steps with overlap > 0
  double duration;  // steps * dt
};

// particle-level coefficients: m_eff of two particles, absolute damping giving e = kTargetE
double particle_m_eff() { return 0.5 * kRho * M_PI / 6.0 * kDp * kDp * kDp; }
double particle_gamma_abs()
{
  const double ln = std::log(kTargetE), zeta = -ln / std::sqrt(M_PI * M_PI + ln * ln);
  return 2.0 * zeta * std::sqrt(kKn * particle_m_eff());
}

void set_variable(Session& s, const std::string& name, double value)
{
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  s.cmd("variable " + name + " equal " + buf);
}

// Steps one DEM step at a time until the contact is over: gap() < 0 while in contact, relative_velocity() of
// the parcels (or of the parcel against the wall) before the contact was v_before.
Collision measure(Session& s, const std::function<double()>& gap, const std::function<double()>& relative_velocity,
                  double v_before, double dt)
{
  long steps = 0;
  bool touched = false;
  for (int n = 0; n < 200000; ++n) {
    s.cmd("run 1 pre no post no");
    if (gap() < 0) {
      ++steps;
      touched = true;
    } else if (touched) {
      return {-relative_velocity() / v_before, steps, steps * dt};
    }
  }
  ADD_FAILURE() << "the contact did not end";
  return {0, 0, 0};
}

// x, z position and x, z velocity of every atom (on any rank), by tag
std::map<int, std::array<double, 4>> atom_states(Session& s)
{
  LAMMPS_NS::Atom* atom = s.lmp()->atom;
  return gather_by_tag<4>(s.lmp(), [&](int i) {
    return std::array<double, 4>{atom->x[i][0], atom->x[i][2], atom->v[i][0], atom->v[i][2]};
  });
}

Collision collide(double l, bool absolute, double dt, const char* scaling = "linear")
{
  const double D = kDp * l, np = l * l * l;
  const double g_abs = particle_gamma_abs(), m_eff = particle_m_eff();
  Session s("none");
  auto var = [&](const std::string& name, double value) { set_variable(s, name, value); };
  var("D", D);
  var("x0", 0.5 * D * 1.05);
  var("skin", 0.2 * D);
  var("kn", kKn);
  var("kt", 2.0 / 7.0 * kKn);
  var("gn", absolute ? g_abs : g_abs / m_eff);
  var("gt", absolute ? 0.5 * g_abs : 0.5 * g_abs / m_eff);
  var("dt", dt);
  s.cmd(std::string("variable gname string ") + (absolute ? "gamman_abs" : "gamman"));
  s.cmd(std::string("variable gtname string ") + (absolute ? "gammat_abs" : "gammat"));
  s.cmd(std::string("variable absolute string ") + (absolute ? "on" : "off"));
  s.file(kDir + "/collision.in");
  char fix[128];
  std::snprintf(fix, sizeof fix, "fix p all parcel mode constant_np np %.17g scaling %s", np, scaling);
  s.cmd(fix);
  s.cmd("run 0");

  std::map<int, std::array<double, 4>> st;
  return measure(
      s, [&]() { st = atom_states(s); return st.at(2)[0] - st.at(1)[0] - D; },
      [&]() { return st.at(2)[2] - st.at(1)[2]; }, -1.0, dt);
}

// dp_by_type: parcels of 4 mm holding 1 mm (type 1, np 64) and 2 mm (type 2, np 8) particles, scaling linear.
constexpr double kParcelD = 0.004, kDpSmall = 0.001, kDpLarge = 0.002;
double particle_mass(double d) { return kRho * M_PI / 6.0 * d * d * d; }

// A type-1 parcel hitting a type-2 parcel (against_wall false) or the wall, with the particle-level
// mass-specific dampings g12 (types 1-2) and g13 (type 1 - wall).
Collision collide_by_type(bool against_wall, double g12, double g13, double dt,
                          const char* fix_args = "mode constant_diameter diameter 0.004 dp_by_type 0.001 0.002 none "
                                                 "scaling linear")
{
  Session s("none");
  set_variable(s, "D", kParcelD);
  set_variable(s, "x0", 0.5 * kParcelD * 1.05);
  set_variable(s, "skin", 0.2 * kParcelD);
  set_variable(s, "kn", kKn);
  set_variable(s, "kt", 2.0 / 7.0 * kKn);
  set_variable(s, "g12", g12);
  set_variable(s, "g13", g13);
  set_variable(s, "dt", dt);
  set_variable(s, "against_wall", against_wall ? 1 : 0);
  s.file(kDir + "/collision_types.in");
  s.cmd(std::string("fix p all parcel ") + fix_args);
  s.cmd("run 0");
  std::map<int, std::array<double, 4>> st;
  if (against_wall)
    return measure(
        s, [&]() { st = atom_states(s); return st.at(1)[1] - 0.5 * kParcelD; }, [&]() { return st.at(1)[3]; }, -1.0,
        dt);
  return measure(
      s, [&]() { st = atom_states(s); return st.at(2)[0] - st.at(1)[0] - kParcelD; },
      [&]() { return st.at(2)[2] - st.at(1)[2]; }, -1.0, dt);
}

}  // namespace

TEST(ParcelCollision, LinearScalingKeepsRestitutionAndScalesDuration)
{
  const double m_eff = particle_m_eff(), g_abs = particle_gamma_abs();
  const double e_particle = restitution_coefficient(kKn, g_abs, m_eff);
  const double tc1 = contact_duration(kKn, g_abs, m_eff);
  const double dt = tc1 / 100.0;
  PF_PRINT("[ collision ] particle: dp %.3g m, kn %.4g N/m, gamman_abs %.5g kg/s (gamman %.5g 1/s): analytic "
           "e = %.6f, t_c = %.5g s; dt = t_c/100\n", kDp, kKn, g_abs, g_abs / m_eff, e_particle, tc1);
  for (bool absolute : {false, true}) {
    Collision ref{};
    for (double l : {1.0, 2.0, 4.0}) {
      const Collision c = collide(l, absolute, dt);
      if (l == 1.0) ref = c;
      const double e_err = c.e / e_particle - 1.0;
      const double duration_ratio = static_cast<double>(c.steps) / ref.steps;
      const double t_err = c.duration / (l * tc1) - 1.0;
      PF_PRINT("[ collision ] absolute_damping %-3s l = %.0f (np %3.0f): e = %.6f (error vs particle %+.3f %%), "
               "contact %ld steps = %.5g s, duration ratio to l=1: %.4f (l = %.0f, error %+.2f %%), vs l t_c: %+.2f %%\n",
               absolute ? "on" : "off", l, l * l * l, c.e, 100 * e_err, c.steps, c.duration, duration_ratio, l,
               100 * (duration_ratio / l - 1), 100 * t_err);
      EXPECT_LT(std::fabs(e_err), 0.01);
      EXPECT_LT(std::fabs(duration_ratio / l - 1.0), 0.02);  // +-1 step of 100 at l = 1
    }
  }
  // control: without scaling (absolute damping) the parcel contact is softer relative to its mass: t_c grows
  // about as l^(3/2) and the restitution changes, so the test above does see the scaling
  const Collision ref = collide(1.0, true, dt, "none"), c = collide(4.0, true, dt, "none");
  const double z1 = damping_ratio(kKn, g_abs, m_eff), z4 = damping_ratio(kKn, g_abs, 64 * m_eff);
  const double expected_ratio = 8.0 * std::sqrt(1 - z1 * z1) / std::sqrt(1 - z4 * z4);
  PF_PRINT("[ collision ] control, scaling none, absolute damping, l = 4: e = %.6f (analytic %.6f, particle %.6f), "
           "duration ratio to l=1: %.3f (analytic %.3f)\n", c.e, restitution_coefficient(kKn, g_abs, 64 * m_eff),
           e_particle, static_cast<double>(c.steps) / ref.steps, expected_ratio);
  EXPECT_NEAR(static_cast<double>(c.steps) / ref.steps, expected_ratio, 0.05);
  EXPECT_GT(c.e, e_particle + 0.1);
}

TEST(ParcelCollision, DiameterByTypeKeepsRestitutionOfEachPair)
{
  // the particle pairs: 1 mm with 2 mm (m_eff = m1 m2/(m1 + m2)) and 1 mm with the wall (m_eff = m1), each with
  // the mass-specific damping that gives e = kTargetE
  const double m1 = particle_mass(kDpSmall), m2 = particle_mass(kDpLarge);
  const double ln = std::log(kTargetE), zeta = -ln / std::sqrt(M_PI * M_PI + ln * ln);
  struct Pair {
    const char* name;
    bool against_wall;
    double m_eff, l;
  };
  const Pair pairs[] = {{"types 1-2", false, m1 * m2 / (m1 + m2), std::cbrt(0.5 * (64.0 + 8.0))},
                        {"type 1 - wall", true, m1, kParcelD / kDpSmall}};
  const double g12 = 2.0 * zeta * std::sqrt(kKn / pairs[0].m_eff), g13 = 2.0 * zeta * std::sqrt(kKn / pairs[1].m_eff);
  const double dt = contact_duration(kKn, g12 * pairs[0].m_eff, pairs[0].m_eff) / 100.0;
  for (const Pair& p : pairs) {
    const double g = p.against_wall ? g13 : g12;
    const double e_particle = restitution_coefficient(kKn, g * p.m_eff, p.m_eff);
    const double tc_particle = contact_duration(kKn, g * p.m_eff, p.m_eff);
    const Collision c = collide_by_type(p.against_wall, g12, g13, dt);
    const double e_err = c.e / e_particle - 1.0, t_err = c.duration / (p.l * tc_particle) - 1.0;
    PF_PRINT("[ collision ] dp_by_type 1/2 mm in 4 mm parcels, %s: l = %.6f; e = %.6f (particle pair %.6f, error "
             "%+.3f %%), contact %ld steps = %.5g s (l t_c of the particle pair %.5g s, error %+.2f %%)\n",
             p.name, p.l, c.e, e_particle, 100 * e_err, c.steps, c.duration, p.l * tc_particle, 100 * t_err);
    EXPECT_LT(std::fabs(e_err), 0.01);
    EXPECT_LT(std::fabs(t_err), 0.02);
  }
}

TEST(ParcelCollision, ShearStressLowersTheParcelRestitutionOnly)
{
  // np 1.5 (l = 1.145): with the particles' 0.7, e' = sqrt(1 - l^4 0.51) = 0.351
  const double m_eff = particle_m_eff(), g_abs = particle_gamma_abs();
  const double l = std::cbrt(1.5), expected = shear_stress_restitution(kTargetE, l);
  const double dt = contact_duration(kKn, g_abs, m_eff) / 100.0;
  for (bool absolute : {false, true}) {
    const Collision c = collide(l, absolute, dt, "linear shear_stress 0.7");
    PF_PRINT("[ collision ] shear_stress 0.7, np 1.5, absolute_damping %-3s: e = %.6f (1 - e'^2 = l^4 (1 - e^2): "
             "%.6f, error %+.3f %%)\n", absolute ? "on" : "off", c.e, expected, 100 * (c.e / expected - 1));
    EXPECT_LT(std::fabs(c.e / expected - 1.0), 0.01);
  }
  // np 8 parcels of 4 mm (2 mm particles, restitution 0.97 between them, 0.7 against the wall z = 0, type 3 and
  // defined before the fix): two parcels (types 1 and 2) reach e' = 0.233, the wall contact keeps its 0.7
  const double m_eff22 = 0.5 * particle_mass(kDpLarge), m_wall = particle_mass(kDpLarge);
  const double g12 = 2.0 * damping_ratio_of_restitution(0.97) * std::sqrt(kKn / m_eff22);
  const double g13 = 2.0 * damping_ratio_of_restitution(kTargetE) * std::sqrt(kKn / m_wall);
  const double dt_types = contact_duration(kKn, g12 * m_eff22, m_eff22) / 100.0;
  const char* linear = "mode constant_np np 8 scaling linear";
  const char* shear = "mode constant_np np 8 scaling linear shear_stress 0.97";
  const Collision wall = collide_by_type(true, g12, g13, dt_types, linear);
  const Collision wall_shear = collide_by_type(true, g12, g13, dt_types, shear);
  const Collision pair = collide_by_type(false, g12, g13, dt_types, linear);
  const Collision pair_shear = collide_by_type(false, g12, g13, dt_types, shear);
  const double expected_pair = shear_stress_restitution(0.97, 2.0);
  PF_PRINT("[ collision ] np 8, scaling linear / with shear_stress 0.97: against the wall e = %.9f / %.9f, two "
           "parcels e = %.6f / %.6f (expected 0.97 / %.6f)\n", wall.e, wall_shear.e, pair.e, pair_shear.e,
           expected_pair);
  EXPECT_EQ(wall.e, wall_shear.e);
  EXPECT_EQ(wall.steps, wall_shear.steps);
  EXPECT_NEAR(wall.e, kTargetE, 0.01 * kTargetE);
  EXPECT_NEAR(pair.e, 0.97, 0.01 * 0.97);
  EXPECT_NEAR(pair_shear.e, expected_pair, 0.01 * expected_pair);
}
