// fix ID group parcel mode constant_np np N [scaling none|linear [shear_stress E]]
// fix ID group parcel mode constant_diameter diameter D (dp d | distribution d1 f1 d2 f2 ... |
//                     dp_by_type d1 d2 ... dN) [seed S] [scaling none|linear [shear_stress E]]
//
// Makes the spheres of the group coarse-grained parcels: per-atom real particle diameter dp and real
// particles per parcel np (columns 1 and 2 of the per-atom array: `dump custom ... f_ID[1] f_ID[2]`).
// dp and np migrate with atoms, are written to restart files and are set for every atom created later
// (fix insert/pack etc.). With `scaling linear` it scales the hooke/stiffness coefficients of
// `fix property/global kn/kt/gamman/gammat(_abs)` in place, once; `shear_stress E` (E: the particles'
// restitution) raises the parcel-parcel dampings further, to 1 - e'^2 = l^4 (1 - E^2), so that the parcels
// carry the particles' collisional shear stress. Full documentation: README.md.
#pragma once

#include <memory>
#include <set>
#include <string>
#include <vector>

#include "liggghts_plugins/contact_scaling.h"
#include "liggghts_plugins/per_atom_columns_fix.h"
#include "liggghts_plugins/parcel_settings.h"
#include "liggghts_plugins/size_class_sequence.h"

namespace parcelflow::plugins {

class FixParcel : public PerAtomColumnsFix {
 public:
  enum Column { DP = 0, NP = 1, NCOLUMNS = 2 };

  FixParcel(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg);

  int setmask() override;
  void post_create() override;
  void pre_delete(bool unfixflag) override;
  void init() override;
  void setup(int vflag) override;
  void pre_force(int vflag) override;

  void set_arrays(int i) override;
  void write_restart(FILE* fp) override;
  void restart(char* buf) override;

  // Coupling interface: local atoms 0..nlocal-1; re-fetch after every run (atoms move and reorder).
  double dp(int i) const { return data_[i][DP]; }
  double np(int i) const { return data_[i][NP]; }
  const ParcelSettings& settings() const { return settings_; }
  // parcels that got a size class from the distribution so far (all ranks)
  double parcels_assigned() const { return assigned_; }

 private:
  void assign(int i);
  void resolve_pending();
  void apply_scaling();
  double shear_stress_damping(int type_i, int type_j) const;
  void check_one_density();
  void check_wall_types();
  void print_contact_values();
  void warn_geometric_limits();
  [[noreturn]] void fail(const std::string& msg);

  ParcelSettings settings_;
  std::unique_ptr<SizeClassSequence> sequence_;
  double assigned_ = 0.0;          // parcels numbered in the size-class sequence (global)
  bool needs_sequence_ = false;    // constant_diameter with more than one size class
  ContactScaling scaling_;
  std::set<int> walls_;  // the wall types when the contacts were scaled
  bool printed_ = false;
  bool limits_checked_ = false;  // at the first setup with atoms in the group
};

}  // namespace parcelflow::plugins
