// In-place linear collision scaling of LIGGGHTS' hooke/stiffness coefficients (used by fix parcel).
//
// The coefficients live in `fix property/global kn|kt|gamman|gammat|gamman_abs|gammat_abs peratomtypepair`.
// LIGGGHTS copies them into the contact model at the start of every run (Force::init, before any fix's
// init), so they are scaled in place once, when fix parcel is defined, and restored on unfix.
#pragma once

#include <functional>
#include <set>
#include <string>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
class FixPropertyGlobal;
}  // namespace LAMMPS_NS

namespace parcelflow::plugins {

class ContactScaling {
 public:
  // l(type_i, type_j) (1-based) for every type pair: the scale factor of the contact of the two types.
  using PairScaleFactor = std::function<double(int, int)>;

  // Multiplies every coefficient present, per type pair, by its factor for that pair's l (kn, kt: l;
  // gamman, gammat: 1/l; gamman_abs, gammat_abs: l^2), the dampings also by damping(type_i, type_j).
  // `ntypes` > 0: l is defined for types 1..ntypes only, and every coefficient must be an ntypes x ntypes
  // matrix; 0: l is defined for any type. Returns "" on success, else a message; then nothing stays scaled.
  std::string apply(LAMMPS_NS::LAMMPS* lmp, const PairScaleFactor& l, const PairScaleFactor& damping, int ntypes,
                    const char* caller);
  // Restores the original values of the fixes that still hold the scaled ones.
  void undo(LAMMPS_NS::LAMMPS* lmp);
  // "" if every scaled fix still exists with the scaled values, else a message naming it.
  std::string check_intact(LAMMPS_NS::LAMMPS* lmp, const char* fix_id) const;
  // One line per coefficient: "  kn (fix kn, x 2): 1000 -> 2000", or with factors that differ between
  // type pairs "  kn (fix kn, per type pair): 100 -> 333.333 100 -> 282.388 ...".
  std::string describe() const;
  bool applied() const { return !scaled_.empty(); }

  // "" if pair_style gran and every fix wall/gran use model hooke/stiffness without cohesion and rolling
  // friction (what linear scaling can scale), else a message.
  static std::string check_contact_models(LAMMPS_NS::LAMMPS* lmp);
  // The atom types of the walls defined so far: of every fix wall/gran (a primitive's, or its meshes').
  static std::set<int> wall_types(LAMMPS_NS::LAMMPS* lmp);

 private:
  struct ScaledProperty {
    std::string name;  // kn, kt, gamman, gammat, gamman_abs, gammat_abs
    std::string fix_id;
    LAMMPS_NS::FixPropertyGlobal* fix = nullptr;
    std::vector<double> factors, original, scaled;  // per value, row-major type pairs
  };
  std::vector<ScaledProperty> scaled_;
};

}  // namespace parcelflow::plugins
