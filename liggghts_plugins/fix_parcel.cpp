#include "liggghts_plugins/fix_parcel.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <sstream>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "liggghts_plugins/fix_support.h"
#include "liggghts_plugins/geometric_limits.h"
#include "group.h"
#include "modify.h"
#include "liggghts_plugins/parcel_math.h"

using namespace LAMMPS_NS;
using namespace LAMMPS_NS::FixConst;

namespace parcelflow::plugins {
namespace {

constexpr double kDiameterTolerance = 1e-6;  // relative; inserted diameter vs. parcel diameter D
constexpr double kDensityTolerance = 1e-9;   // relative; one density for dp_by_type with scaling linear
// 2 added the dp_by_type diameters; files of version 1 are still read
constexpr int kRestartVersion = 2;

}  // namespace

FixParcel::FixParcel(LAMMPS* lmp, int narg, char** arg) : PerAtomColumnsFix(lmp, narg, arg, NCOLUMNS)
{
  try {
    settings_ = parse_parcel_settings(style_arguments(narg, arg));
  } catch (const ArgumentError& e) {
    fail(e.what());
  }
  if (!atom->radius_flag || !atom->rmass_flag)
    fail("fix parcel: needs per-atom radius and mass (atom_style sphere or granular)");
  if (!atom->tag_enable) fail("fix parcel: needs atom IDs (atom_modify id yes)");
  if (settings_.by_type() && static_cast<int>(settings_.type_diameters.size()) != atom->ntypes)
    fail("fix parcel: keyword 'dp_by_type' got " + std::to_string(settings_.type_diameters.size()) +
         " values but the box has " + std::to_string(atom->ntypes) + " atom types; allowed: one value per atom type 1.." +
         std::to_string(atom->ntypes) + " (a particle diameter, or none for a type without parcels such as the walls)");

  needs_sequence_ = settings_.mode == ParcelMode::ConstantDiameter && settings_.classes.size() > 1;
  if (needs_sequence_) {
    std::vector<double> fractions;
    for (const SizeClass& c : settings_.classes) fractions.push_back(c.mass_fraction);
    sequence_ = std::make_unique<SizeClassSequence>(fractions, settings_.seed);
  }

  restart_global = 1;
  // Atoms that exist now get their parcel values at the first setup (Modify::setup calls set_arrays for
  // the group, unless a restart file restored them), so a later `set ... diameter` is taken into account.
  for (int i = 0; i < atom->nlocal; ++i) {
    data_[i][DP] = 2.0 * atom->radius[i];
    data_[i][NP] = 1.0;
  }
}

void FixParcel::fail(const std::string& msg)
{
  error->all(FLERR, msg.c_str());
  throw ArgumentError(msg);  // not reached: error->all ends the program
}

int FixParcel::setmask() { return needs_sequence_ ? PRE_FORCE : 0; }

// ------------------------------------------------------------------ per-atom values

void FixParcel::assign(int i)
{
  const double diameter = 2.0 * atom->radius[i];
  double* d = data_[i];
  if (!(atom->mask[i] & groupbit)) {  // not a parcel of this fix: a plain sphere
    d[DP] = diameter;
    d[NP] = 1.0;
    return;
  }
  if (settings_.shear_stress_restitution > 0.0 && walls_.count(atom->type[i])) {
    const std::string msg = "fix " + std::string(id) + " parcel: keyword 'shear_stress' keeps the walls' contacts, "
                            "but a parcel has the walls' atom type " + std::to_string(atom->type[i]) +
                            ", so its contacts were kept too; allowed: walls of an atom type that no parcel has";
    error->one(FLERR, msg.c_str());
  }
  if (settings_.mode == ParcelMode::ConstantNp) {
    d[NP] = settings_.np;
    d[DP] = particle_diameter(diameter, settings_.np);
    return;
  }
  const double D = settings_.parcel_diameter;
  if (std::fabs(diameter - D) > kDiameterTolerance * D) {
    char who[64];
    if (atom->tag[i] > 0) std::snprintf(who, sizeof who, "atom %ld", static_cast<long>(atom->tag[i]));
    else std::snprintf(who, sizeof who, "an inserted atom");
    char msg[512];
    std::snprintf(msg, sizeof msg,
                  "fix %s parcel: %s has diameter %.9g but 'mode constant_diameter diameter' is %.9g; "
                  "insert spheres of diameter D (radius %.9g) into group %s",
                  id, who, diameter, D, 0.5 * D, group->names[igroup]);
    error->one(FLERR, msg);
  }
  if (settings_.by_type()) {
    const double dp = settings_.type_diameters[atom->type[i] - 1];
    if (dp == kNoParcels) {
      char msg[512];
      std::snprintf(msg, sizeof msg,
                    "fix %s parcel: an atom of type %d is in group %s, but 'dp_by_type' gives none for type %d; "
                    "allowed: parcels of the types with a diameter, or atoms outside the fix group",
                    id, atom->type[i], group->names[igroup], atom->type[i]);
      error->one(FLERR, msg);
    }
    d[DP] = dp;
    d[NP] = particles_per_parcel(D, dp);
  } else if (!needs_sequence_) {
    d[DP] = settings_.classes.front().diameter;
    d[NP] = particles_per_parcel(D, d[DP]);
  } else {
    d[DP] = -1.0;  // pending: the size class needs the atom ID, which fix insert assigns later
    d[NP] = -1.0;
  }
}

void FixParcel::resolve_pending()
{
  if (!needs_sequence_) return;
  std::vector<int> local;
  std::vector<tagint> tags;
  for (int i = 0; i < atom->nlocal; ++i)
    if (data_[i][DP] < 0.0) {
      local.push_back(i);
      tags.push_back(atom->tag[i]);
    }
  const int n = static_cast<int>(local.size());
  std::vector<int> counts(comm->nprocs), displs(comm->nprocs, 0);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  long total = 0;
  for (int p = 0; p < comm->nprocs; ++p) {
    displs[p] = static_cast<int>(total);
    total += counts[p];
  }
  if (total == 0) return;
  std::vector<tagint> all(total);
  MPI_Allgatherv(tags.data(), n, MPI_LMP_TAGINT, all.data(), counts.data(), displs.data(), MPI_LMP_TAGINT,
                 world);
  std::sort(all.begin(), all.end());
  // parcels are numbered in the order of their IDs: the same numbering on every rank count
  const double D = settings_.parcel_diameter;
  for (int k = 0; k < n; ++k) {
    if (tags[k] <= 0) error->one(FLERR, "fix parcel: a parcel has no atom ID; size classes need IDs");
    const auto pos = std::lower_bound(all.begin(), all.end(), tags[k]) - all.begin();
    const auto index = static_cast<std::uint64_t>(assigned_) + static_cast<std::uint64_t>(pos);
    const SizeClass& c = settings_.classes[sequence_->class_of(index)];
    data_[local[k]][DP] = c.diameter;
    data_[local[k]][NP] = particles_per_parcel(D, c.diameter);
  }
  assigned_ += static_cast<double>(total);
}

void FixParcel::setup(int)
{
  resolve_pending();
  if (!printed_) {
    printed_ = true;
    print_contact_values();
  }
  if (!limits_checked_) warn_geometric_limits();
}

void FixParcel::pre_force(int) { resolve_pending(); }

void FixParcel::set_arrays(int i) { assign(i); }

// ------------------------------------------------------------------ global restart

void FixParcel::write_restart(FILE* fp)
{
  std::vector<double> list = {double(kRestartVersion),
                              double(static_cast<int>(settings_.mode)),
                              settings_.np,
                              settings_.parcel_diameter,
                              double(settings_.seed),
                              double(static_cast<int>(settings_.scaling)),
                              double(settings_.classes.size())};
  for (const SizeClass& c : settings_.classes) {
    list.push_back(c.diameter);
    list.push_back(c.mass_fraction);
  }
  list.push_back(double(settings_.type_diameters.size()));
  list.insert(list.end(), settings_.type_diameters.begin(), settings_.type_diameters.end());
  list.push_back(assigned_);
  write_global_state(comm->me, fp, list);
}

void FixParcel::restart(char* buf)
{
  const double* list = reinterpret_cast<const double*>(buf);
  const int version = static_cast<int>(list[0]);
  if (version != 1 && version != kRestartVersion)
    fail("fix parcel: the restart file holds an unknown version of this fix's state");
  std::size_t n = 1;
  const int mode = static_cast<int>(list[n++]);
  const double np = list[n++], D = list[n++];
  n += 2;  // seed, scaling
  const std::size_t nclasses = static_cast<std::size_t>(list[n++]);
  bool same = mode == static_cast<int>(settings_.mode) && np == settings_.np && D == settings_.parcel_diameter &&
              nclasses == settings_.classes.size();
  for (std::size_t k = 0; k < nclasses; ++k, n += 2)
    if (same && (list[n] != settings_.classes[k].diameter || list[n + 1] != settings_.classes[k].mass_fraction))
      same = false;
  const std::size_t ntypes = version == 1 ? 0 : static_cast<std::size_t>(list[n++]);
  same = same && ntypes == settings_.type_diameters.size() &&
         std::equal(list + n, list + n + ntypes, settings_.type_diameters.begin());
  n += ntypes;
  assigned_ = same ? list[n] : 0.0;
  if (!same && comm->me == 0)
    error->warning(FLERR, "fix parcel: settings differ from the restart file; dp and np of the restored "
                          "parcels are kept, parcels inserted from now on follow the new settings");
}

// ------------------------------------------------------------------ collision scaling

void FixParcel::post_create() { apply_scaling(); }

void FixParcel::pre_delete(bool unfixflag)
{
  if (unfixflag) scaling_.undo(lmp);  // unfix, or the fix is redefined with the same ID
}

void FixParcel::apply_scaling()
{
  if (settings_.scaling != CollisionScaling::Linear || scaling_.applied()) return;
  if (igroup != 0)
    fail(std::string("fix parcel: scaling linear changes the contact coefficients of every type pair, so the "
                     "fix group must be 'all' (got '") + group->names[igroup] + "')");
  for (int k = 0; k < modify->nfix; ++k) {
    auto* other = dynamic_cast<FixParcel*>(modify->fix[k]);
    if (other && other != this && other->settings_.scaling == CollisionScaling::Linear)
      fail(std::string("fix parcel: fix ") + other->id + " already scales the contact coefficients; only one "
           "fix parcel may use scaling linear");
  }
  const ParcelSettings& s = settings_;
  walls_ = ContactScaling::wall_types(lmp);
  const auto l = [&s](int type_i, int type_j) { return s.pair_scale_factor(type_i, type_j); };
  const std::string msg = scaling_.apply(lmp, l, [this](int i, int j) { return shear_stress_damping(i, j); },
                                         s.by_type() ? static_cast<int>(s.type_diameters.size()) : 0, style);
  if (!msg.empty()) fail(msg);
}

// The factor on the linearly scaled dampings of a type pair for keyword shear_stress: the ratio of the damping
// ratios of e' and e (mass-specific or absolute alike); 1 for a wall or a type without parcels, and without it.
double FixParcel::shear_stress_damping(int type_i, int type_j) const
{
  const ParcelSettings& s = settings_;
  const double e = s.shear_stress_restitution;
  const auto parcels = [&](int t) {
    return !walls_.count(t) && !(s.by_type() && s.type_diameters.at(t - 1) == kNoParcels);
  };
  if (e == 0.0 || !parcels(type_i) || !parcels(type_j)) return 1.0;
  const double e_parcels = shear_stress_restitution(e, s.pair_scale_factor(type_i, type_j));
  return damping_ratio_of_restitution(e_parcels) / damping_ratio_of_restitution(e);
}

void FixParcel::init()
{
  if (settings_.scaling != CollisionScaling::Linear) return;
  std::string msg = scaling_.check_intact(lmp, id);
  if (msg.empty()) msg = ContactScaling::check_contact_models(lmp);
  if (!msg.empty()) fail(msg);
  if (settings_.by_type()) check_one_density();
  if (settings_.shear_stress_restitution > 0.0) check_wall_types();
}

// shear_stress tells walls from parcels by atom type: the walls' types as the contacts were scaled must still
// be all of them (a parcel of a wall type is refused as it is assigned).
void FixParcel::check_wall_types()
{
  for (int type : ContactScaling::wall_types(lmp))
    if (!walls_.count(type))
      fail("fix " + std::string(id) + " parcel: keyword 'shear_stress' made the contacts of atom type " +
           std::to_string(type) + " more dissipative as parcels', but a wall defined after the fix uses that type; "
           "allowed: walls (fix wall/gran) defined before fix parcel");
}

// The pair rule of dp_by_type (equal_mass_pair_scale_factor) holds for parcels of one mass, i.e. of one
// density, since they have one diameter. Atoms inserted in a run are checked at the next run's start.
void FixParcel::check_one_density()
{
  double range[2] = {-INFINITY, -INFINITY};  // {-lowest, highest} density of the fix's atoms
  for (int i = 0; i < atom->nlocal; ++i)
    if (atom->mask[i] & groupbit) {
      range[0] = std::max(range[0], -atom->density[i]);
      range[1] = std::max(range[1], atom->density[i]);
    }
  double global[2];
  MPI_Allreduce(range, global, 2, MPI_DOUBLE, MPI_MAX, world);
  const double lowest = -global[0], highest = global[1];
  if (highest - lowest > kDensityTolerance * highest) {
    char msg[512];
    std::snprintf(msg, sizeof msg,
                  "fix %s parcel: scaling linear with dp_by_type scales each type pair for parcels of one mass, "
                  "but the parcels' densities range from %.9g to %.9g; allowed: one particle density for every "
                  "type (or scaling none)", id, lowest, highest);
    fail(msg);
  }
}

// Once, at the first setup with parcels in the group (atoms inserted during a run are seen at the next).
void FixParcel::warn_geometric_limits()
{
  double largest[3] = {0.0, 0.0, 0.0};  // D, l = D/dp, whether the group holds an atom
  for (int i = 0; i < atom->nlocal; ++i)
    if ((atom->mask[i] & groupbit) && data_[i][NP] > 0.0) {
      largest[0] = std::max(largest[0], 2.0 * atom->radius[i]);
      largest[1] = std::max(largest[1], 2.0 * atom->radius[i] / data_[i][DP]);
      largest[2] = 1.0;
    }
  MPI_Allreduce(MPI_IN_PLACE, largest, 3, MPI_DOUBLE, MPI_MAX, world);
  limits_checked_ = largest[2] > 0.0;
  const std::string text = geometric_limits_warning(id, largest[0], largest[1]);
  if (!text.empty() && comm->me == 0) error->warning(FLERR, text.c_str());
}

void FixParcel::print_contact_values()
{
  if (comm->me != 0) return;
  std::ostringstream out;
  out.precision(6);
  out << "fix " << id << " parcel: mode " << to_string(settings_.mode) << ", scaling "
      << to_string(settings_.scaling);
  if (settings_.scaling == CollisionScaling::Linear && settings_.by_type()) {
    out << ", l of each type pair (D/dp of a parcel type with itself and with a type without parcels, "
           "((np_i + np_j)/2)^(1/3) of two parcel types):";
    const int ntypes = static_cast<int>(settings_.type_diameters.size());
    for (int ti = 1; ti <= ntypes; ++ti)
      for (int tj = ti; tj <= ntypes; ++tj) out << " " << ti << "-" << tj << " " << settings_.pair_scale_factor(ti, tj);
    out << "; contact coefficients in force:\n" << scaling_.describe();
  } else if (settings_.scaling == CollisionScaling::Linear) {
    out << ", l = D/dp = " << settings_.uniform_scale_factor() << "; contact coefficients in force:\n"
        << scaling_.describe();
  } else {
    out << ": contact coefficients used as given\n";
  }
  if (settings_.shear_stress_restitution > 0.0) {
    const double e = settings_.shear_stress_restitution;
    out << "  shear_stress: parcel-parcel dampings raised from restitution " << e << " to "
        << shear_stress_restitution(e, settings_.largest_parcel_pair_scale_factor())
        << " at the largest l (1 - e'^2 = l^4 (1 - e^2)); the contacts with wall types";
    for (int type : walls_) out << " " << type;
    out << (walls_.empty() ? " (none defined)" : "") << " keep theirs\n";
  }
  if (screen) fputs(out.str().c_str(), screen);
  if (logfile) fputs(out.str().c_str(), logfile);
}

}  // namespace parcelflow::plugins
