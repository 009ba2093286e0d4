// Settings of `fix ID group parcel ...` and their parser. Plain C++ (no LIGGGHTS) so that every argument
// error can be unit-tested: the parser throws ArgumentError, the fix turns it into error->all.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace parcelflow::plugins {

// A bad argument: the message names the keyword, the value given and what is allowed.
class ArgumentError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct SizeClass {
  double diameter;       // real particle diameter dp [m]
  double mass_fraction;  // mass fraction of the class (all classes sum to 1)
};

enum class ParcelMode { ConstantNp, ConstantDiameter };
enum class CollisionScaling { None, Linear };

// dp_by_type value of an atom type that holds no parcels of the fix (`none`, e.g. the wall type).
constexpr double kNoParcels = 0.0;

struct ParcelSettings {
  ParcelMode mode = ParcelMode::ConstantNp;
  double np = 1.0;                  // constant_np: real particles per parcel (>= 1)
  double parcel_diameter = 0.0;     // constant_diameter: parcel (collision) diameter D
  std::vector<SizeClass> classes;   // constant_diameter: one class (`dp`) or a distribution
  // constant_diameter with dp_by_type: entry t-1 is the real particle diameter of atom type t, or
  // kNoParcels; empty otherwise
  std::vector<double> type_diameters;
  std::uint32_t seed = 12345679;    // orders classes with equal fractions in the assignment sequence
  CollisionScaling scaling = CollisionScaling::None;
  // shear_stress E (scaling linear only): E is the particles' restitution, which the script's dampings give;
  // parcel-parcel contacts are made more dissipative, 1 - e'^2 = l^4 (1 - E^2) (parcel_math.h). 0: off.
  double shear_stress_restitution = 0.0;

  bool by_type() const { return !type_diameters.empty(); }
  // l = D/dp if it is the same for every parcel of the fix (constant_np, or a single size class `dp`);
  // 0 otherwise (a distribution, or dp_by_type).
  double uniform_scale_factor() const;
  // l of the contact between atom types type_i and type_j (1-based) under scaling linear: the uniform l,
  // or with dp_by_type equal_mass_pair_scale_factor (parcel_math.h) of the two types' np, D/dp of the parcel type
  // against a type without parcels (a wall), and 1 between two types without parcels (no such contact).
  double pair_scale_factor(int type_i, int type_j) const;
  // The largest l of a contact of two parcels (types without parcels excluded).
  double largest_parcel_pair_scale_factor() const;
};

// Parses the arguments after the style name, e.g. {"mode","constant_np","np","8","scaling","linear"}.
ParcelSettings parse_parcel_settings(const std::vector<std::string>& args);

// Whether the whole token is a finite number.
bool is_number(const std::string& token);

// Strict number parsing: the whole token must be a finite number. Throws ArgumentError naming keyword.
double parse_number(const std::string& keyword, const std::string& token);

const char* to_string(ParcelMode mode);
const char* to_string(CollisionScaling scaling);

}  // namespace parcelflow::plugins
