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

struct ParcelSettings {
  ParcelMode mode = ParcelMode::ConstantNp;
  double np = 1.0;                  // constant_np: real particles per parcel (>= 1)
  double parcel_diameter = 0.0;     // constant_diameter: parcel (collision) diameter D
  std::vector<SizeClass> classes;   // constant_diameter: one class (`dp`) or a distribution
  std::uint32_t seed = 12345679;    // orders classes with equal fractions in the assignment sequence
  CollisionScaling scaling = CollisionScaling::None;

  // l = D/dp if it is the same for every parcel of the fix (constant_np, or a single size class);
  // 0 otherwise.
  double uniform_scale_factor() const;
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
