#pragma once
// Typed, range-checked access to one map of case.yaml. Every error is a ConfigError naming the full key
// path (e.g. `gas.viscosity`), the offending value and what is allowed. The coupling layer can wrap its
// own sub-nodes of the same file with it.
//
// A section's keys are checked before any of its values is read (allowOnly, singleKey or allowAnyKeys;
// reading first is an internal error): a misspelt required key (`typ: wall`) is then reported as the unknown
// key it is, with the closest allowed name, not as the required key missing.
#include <yaml-cpp/yaml.h>

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "cfd/base/types.hpp"

namespace parcelflow::cfd {

// An interval of allowed numbers; open ends exclude the bound.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool loOpen = false;
  bool hiOpen = false;
  static Range any() { return {}; }
  static Range positive() { return {0.0, std::numeric_limits<double>::infinity(), true, false}; }
  static Range nonNegative() { return {0.0, std::numeric_limits<double>::infinity(), false, false}; }
  static Range closed(double a, double b) { return {a, b, false, false}; }
  static Range leftOpen(double a, double b) { return {a, b, true, false}; }
  bool contains(double v) const;
  std::string describe() const;
};

class YamlSection {
 public:
  // `path` is the dotted key path of `node` ("" for the file's root).
  YamlSection(YAML::Node node, std::string path);

  const std::string& path() const { return path_; }
  std::string keyPath(const std::string& key) const;
  bool has(const std::string& key) const;
  std::vector<std::string> keys() const;
  // Rejects any key not listed (typos must not be ignored silently), naming every unknown key with its
  // value and the closest allowed name.
  void allowOnly(const std::vector<std::string>& keys) const;
  // For maps whose keys are names the caller reads all of (patch names, LIGGGHTS variables) or are checked
  // by another reader (the file's root).
  void allowAnyKeys() const;

  YamlSection map(const std::string& key) const;
  std::vector<YamlSection> listOfMaps(const std::string& key) const;
  double number(const std::string& key, std::optional<double> fallback, Range range) const;
  int integer(const std::string& key, std::optional<int> fallback, int lo, int hi) const;
  std::string word(const std::string& key, std::optional<std::string> fallback,
                   const std::vector<std::string>& allowed) const;
  std::string text(const std::string& key, std::optional<std::string> fallback) const;
  Vec3 vec3(const std::string& key, std::optional<Vec3> fallback, Range range) const;
  std::vector<double> numbers(const std::string& key, std::size_t count, Range range) const;
  std::array<int, 3> int3(const std::string& key, int lo, int hi) const;
  // The only key of a one-key map, checked against `allowed` (used for `{box: {...}}` style choices).
  std::string singleKey(const std::vector<std::string>& allowed) const;

  [[noreturn]] void fail(const std::string& key, const std::string& what) const;

 private:
  bool present(const std::string& key) const;  // has(key), for reading it: the keys must have been checked
  YAML::Node node(const std::string& key) const;
  std::string valueText(const std::string& key) const;
  [[noreturn]] void failUnknown(const std::vector<std::string>& unknown, const std::vector<std::string>& allowed) const;
  YAML::Node node_;
  std::string path_;
  mutable bool keysChecked_ = false;
};

}  // namespace parcelflow::cfd
