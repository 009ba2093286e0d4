#include "liggghts_plugins/fix_parcel_heat.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_property_atom.h"
#include "fix_scalar_transport_equation.h"
#include "liggghts_plugins/fix_support.h"
#include "modify.h"
#include "liggghts_plugins/parcel_heat_step.hpp"
#include "update.h"

using namespace LAMMPS_NS;
using namespace LAMMPS_NS::FixConst;

namespace parcelflow::plugins {

namespace {
constexpr const char* kTemperature = "Temp";         // LIGGGHTS' name, shared with heat/gran/conduction
constexpr const char* kConductionEquation = "heattransfer";  // the equation heat/gran/conduction integrates
}  // namespace

FixParcelHeat::FixParcelHeat(LAMMPS* lmp, int narg, char** arg) : PerAtomColumnsFix(lmp, narg, arg, NCOLUMNS)
{
  try {
    settings_ = parse_parcel_heat_settings(style_arguments(narg, arg), atom->ntypes);
  } catch (const ArgumentError& e) {
    fail(e.what());
  }
  if (!atom->rmass_flag) fail("fix parcel/heat: needs per-atom mass (atom_style sphere or granular)");
  scalar_flag = 1;
  global_freq = 1;
  extscalar = 1;
  for (int i = 0; i < atom->nlocal; ++i) set_arrays(i);
}

void FixParcelHeat::fail(const std::string& msg)
{
  error->all(FLERR, msg.c_str());
  throw ArgumentError(msg);  // not reached: error->all ends the program
}

int FixParcelHeat::setmask() { return FINAL_INTEGRATE; }

void FixParcelHeat::post_create()
{
  temp_ = static_cast<FixPropertyAtom*>(
      modify->find_fix_property(kTemperature, "property/atom", "scalar", 0, 0, style, false));
  if (temp_ && settings_.initial_temperature > 0.0)
    fail("fix parcel/heat: keyword 'initial_temperature' given, but the per-atom temperature Temp exists already "
         "(fix heat/gran/conduction or fix property/atom Temp made it with its own initial value); allowed: leave "
         "out initial_temperature");
  if (temp_) return;
  if (!(settings_.initial_temperature > 0.0))
    fail("fix parcel/heat: keyword 'initial_temperature' is missing and no per-atom temperature Temp exists; "
         "allowed: initial_temperature T0 with T0 > 0 K, or fix heat/gran/conduction defined before this fix");
  std::ostringstream t0;
  t0.precision(17);
  t0 << settings_.initial_temperature;
  const std::string value = t0.str();
  // restart yes, communicated to ghosts (contact conduction reads the neighbours' Temp), no reverse comm
  const char* args[] = {kTemperature, "all", "property/atom", kTemperature, "scalar", "yes", "yes", "no",
                        value.c_str()};
  temp_ = modify->add_fix_property_atom(9, const_cast<char**>(args), style);
}

void FixParcelHeat::check_conduction_fix()
{
  FixScalarTransportEquation* conduction = modify->find_fix_scalar_transport_equation(kConductionEquation);
  if (!conduction) return;
  if (modify->find_fix(conduction->id) > modify->find_fix(id))
    fail("fix parcel/heat: LIGGGHTS' heat equation (fix heat/gran/conduction) is defined after fix parcel/heat; "
         "allowed: fix heat/gran/conduction BEFORE fix parcel/heat, so that the gas exchange is applied last "
         "and implicitly");
  if (conduction->isImplicit())
    fail("fix parcel/heat: LIGGGHTS' heat equation already takes an implicit gas exchange (a CFD convection "
         "fix); allowed: one gas-particle heat exchange, this fix's");
  const double* capacity = conduction->get_capacity();
  if (!capacity)
    fail("fix parcel/heat: fix heat/gran/conduction integrates Temp without a heat capacity; allowed: fix "
         "property/global thermalCapacity peratomtype c_1 ... c_N equal to heat_capacity");
  for (int t = 1; t <= atom->ntypes; ++t)
    if (std::fabs(capacity[t] - settings_.heat_capacity[t - 1]) > 1e-12 * settings_.heat_capacity[t - 1]) {
      std::ostringstream msg;
      msg << "fix parcel/heat: keyword 'heat_capacity' gives " << settings_.heat_capacity[t - 1] << " J/(kg K) for "
          << "atom type " << t << " but fix property/global thermalCapacity, which fix heat/gran/conduction uses, "
          << "gives " << capacity[t] << "; allowed: the same value in both";
      fail(msg.str());
    }
}

void FixParcelHeat::init()
{
  if (!temp_ || modify->find_fix(temp_->id) < 0)
    fail("fix parcel/heat: the per-atom temperature Temp was deleted; allowed: keep fix property/atom Temp");
  check_conduction_fix();
}

void FixParcelHeat::setup(int)
{
  // a temperature at or below 0 K (e.g. from a data file or a set command) stops before any step
  const double* T = temperature();
  double lowest = INFINITY;
  tagint lowest_tag = 0;
  for (int i = 0; i < atom->nlocal; ++i)
    if ((atom->mask[i] & groupbit) && !(T[i] >= lowest)) {
      lowest = T[i];
      lowest_tag = atom->tag[i];
    }
  struct { double value; int rank; } mine{lowest, comm->me}, global{};
  MPI_Allreduce(&mine, &global, 1, MPI_DOUBLE_INT, MPI_MINLOC, world);
  if (!(global.value > 0.0) && global.value != INFINITY) {
    tagint tag = lowest_tag;
    MPI_Bcast(&tag, 1, MPI_LMP_TAGINT, global.rank, world);
    std::ostringstream msg;
    msg << "fix parcel/heat: atom " << tag << " has Temp = " << global.value << " K; allowed: a temperature > 0 K";
    fail(msg.str());
  }
}

double* FixParcelHeat::temperature() { return temp_->vector_atom; }

double FixParcelHeat::heat_capacity(int i) const
{
  return atom->rmass[i] * settings_.heat_capacity[atom->type[i] - 1];
}

void FixParcelHeat::final_integrate()
{
  const double dt = update->dt;
  double* T = temperature();
  const int* mask = atom->mask;
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; ++i) {
    if (!(mask[i] & groupbit)) continue;
    double* d = data_[i];
    const double t_new = implicit_heat_step(heat_capacity(i), T[i], dt, d[CONDUCTANCE], d[GAS_TEMPERATURE], d[SOURCE]);
    d[HEAT_RECEIVED] += dt * (d[CONDUCTANCE] * (d[GAS_TEMPERATURE] - t_new) + d[SOURCE]);
    T[i] = t_new;
  }
}

double FixParcelHeat::compute_scalar()
{
  const double* T = temperature();
  double local = 0.0;
  for (int i = 0; i < atom->nlocal; ++i)
    if (atom->mask[i] & groupbit) local += heat_capacity(i) * T[i];
  double total = 0.0;
  MPI_Allreduce(&local, &total, 1, MPI_DOUBLE, MPI_SUM, world);
  return total;
}

void FixParcelHeat::set_arrays(int i)
{
  for (int c = 0; c < NCOLUMNS; ++c) data_[i][c] = 0.0;
}

}  // namespace parcelflow::plugins
