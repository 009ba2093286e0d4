#include "liggghts_plugins/contact_scaling.h"

#include <algorithm>
#include <sstream>

#include "fix_mesh_surface.h"
#include "fix_property_global.h"
#include "fix_wall_gran.h"
#include "force.h"
#include "lammps.h"
#include "modify.h"
#include "pair_gran.h"
#include "liggghts_plugins/parcel_math.h"

using namespace LAMMPS_NS;

namespace parcelflow::plugins {

namespace {

// The factor of each coefficient for a contact of scale factor l.
double factor_of(const std::string& name, double l)
{
  HookeCoefficients unit;
  unit.kn = unit.kt = unit.gamman = unit.gammat = 1.0;
  unit.absolute_damping = name == "gamman_abs" || name == "gammat_abs";
  const HookeCoefficients rel = scale_linear(unit, l);
  if (name == "kn") return rel.kn;
  if (name == "kt") return rel.kt;
  return name == "gamman" || name == "gamman_abs" ? rel.gamman : rel.gammat;
}

}  // namespace

std::string ContactScaling::apply(LAMMPS* lmp, const PairScaleFactor& l, const PairScaleFactor& damping, int ntypes,
                                  const char* caller)
{
  undo(lmp);
  for (const std::string name : {"kn", "kt", "gamman", "gammat", "gamman_abs", "gammat_abs"}) {
    auto* pg = dynamic_cast<FixPropertyGlobal*>(lmp->modify->find_fix_property(
        name.c_str(), "property/global", "peratomtypepair", 0, 0, caller, false));
    if (!pg) continue;
    const int rows = pg->size_array_rows, cols = pg->size_array_cols;
    if (ntypes > 0 && (rows != ntypes || cols != ntypes)) {
      undo(lmp);
      return "fix parcel: fix property/global " + name + " (ID " + pg->id + ") holds " + std::to_string(rows) +
             " x " + std::to_string(cols) + " values but dp_by_type gives " + std::to_string(ntypes) +
             " atom types; allowed: one row and column per atom type";
    }
    ScaledProperty sp;
    sp.name = name;
    sp.fix_id = pg->id;
    sp.fix = pg;
    double* values = const_cast<double*>(pg->get_values());  // the fix owns a plain malloc'd array
    const bool is_damping = name.compare(0, 5, "gamma") == 0;
    for (int v = 0; v < rows * cols; ++v) {
      const int type_i = v / cols + 1, type_j = v % cols + 1;
      sp.factors.push_back(factor_of(name, l(type_i, type_j)) * (is_damping ? damping(type_i, type_j) : 1.0));
      sp.original.push_back(values[v]);
      values[v] *= sp.factors.back();
      sp.scaled.push_back(values[v]);
    }
    scaled_.push_back(sp);
  }
  auto has = [&](const char* name) {
    return std::any_of(scaled_.begin(), scaled_.end(), [&](const ScaledProperty& s) { return s.name == name; });
  };
  if (!has("kn") || !(has("gamman") || has("gamman_abs"))) {
    undo(lmp);
    return "fix parcel: scaling linear scales model hooke/stiffness and needs 'fix property/global kn "
           "peratomtypepair ...' and 'gamman' (or 'gamman_abs') defined BEFORE fix parcel";
  }
  return "";
}

void ContactScaling::undo(LAMMPS* lmp)
{
  for (ScaledProperty& sp : scaled_) {
    const int k = lmp->modify->find_fix(sp.fix_id.c_str());
    if (k < 0 || lmp->modify->fix[k] != sp.fix) continue;  // the fix was replaced: nothing of ours is left
    double* values = const_cast<double*>(sp.fix->get_values());
    if (!std::equal(sp.scaled.begin(), sp.scaled.end(), values)) continue;
    std::copy(sp.original.begin(), sp.original.end(), values);
  }
  scaled_.clear();
}

std::string ContactScaling::check_intact(LAMMPS* lmp, const char* fix_id) const
{
  for (const ScaledProperty& sp : scaled_) {
    const int k = lmp->modify->find_fix(sp.fix_id.c_str());
    const bool intact = k >= 0 && lmp->modify->fix[k] == sp.fix &&
                        std::equal(sp.scaled.begin(), sp.scaled.end(), sp.fix->get_values());
    if (!intact)
      return "fix parcel: fix property/global " + sp.name + " (ID " + sp.fix_id + ") was redefined after fix " +
             fix_id + " scaled it; define the contact coefficients once, before fix parcel";
  }
  return "";
}

std::string ContactScaling::describe() const
{
  std::ostringstream out;
  out.precision(6);
  for (const ScaledProperty& sp : scaled_) {
    const bool uniform = std::all_of(sp.factors.begin(), sp.factors.end(),
                                     [&](double f) { return f == sp.factors.front(); });
    out << "  " << sp.name << " (fix " << sp.fix_id << ", x ";
    if (uniform) out << sp.factors.front() << "):";
    else out << "per type pair):";
    for (std::size_t v = 0; v < sp.scaled.size(); ++v) out << " " << sp.original[v] << " -> " << sp.scaled[v];
    out << "\n";
  }
  return out.str();
}

std::string ContactScaling::check_contact_models(LAMMPS* lmp)
{
  auto check = [](auto* model, const std::string& where) -> std::string {
    if (!model->contact_match("normal", "hooke/stiffness"))
      return "fix parcel: scaling linear needs model hooke/stiffness, but " + where +
             " uses another normal model; allowed: model hooke/stiffness (for hertz with unchanged material "
             "constants use scaling none)";
    if (!model->contact_match("cohesion", "off"))
      return "fix parcel: scaling linear cannot scale a cohesion model (" + where + "); allowed: cohesion off";
    if (!model->contact_match("rolling_friction", "off"))
      return "fix parcel: scaling linear cannot scale a rolling friction model (" + where +
             "); allowed: rolling_friction off";
    return "";
  };
  if (lmp->force->pair) {
    auto* pg = dynamic_cast<PairGran*>(lmp->force->pair);
    if (!pg)
      return std::string("fix parcel: scaling linear needs pair_style gran, got pair_style ") +
             lmp->force->pair_style;
    if (std::string msg = check(pg, "pair_style gran"); !msg.empty()) return msg;
  }
  for (int k = 0; k < lmp->modify->nfix; ++k)
    if (auto* wall = dynamic_cast<FixWallGran*>(lmp->modify->fix[k]))
      if (std::string msg = check(wall, std::string("fix ") + wall->id); !msg.empty()) return msg;
  return "";
}

std::set<int> ContactScaling::wall_types(LAMMPS* lmp)
{
  std::set<int> types;
  for (int k = 0; k < lmp->modify->nfix; ++k) {
    auto* wall = dynamic_cast<FixWallGran*>(lmp->modify->fix[k]);
    if (!wall) continue;
    if (!wall->is_mesh_wall()) types.insert(wall->atom_type_wall());
    else  // not every mesh is a wall (insertion faces are meshes too): only those of a fix wall/gran
      for (int m = 0; m < wall->n_meshes(); ++m) types.insert(wall->mesh_list()[m]->atomTypeWall());
  }
  return types;
}

}  // namespace parcelflow::plugins
