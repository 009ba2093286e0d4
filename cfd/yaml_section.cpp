#include "yaml_section.hpp"

#include <cmath>

#include "config_error.hpp"
#include "number_text.hpp"

namespace parcelflow::cfd {

namespace {
std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}
}  // namespace

bool Range::contains(double v) const {
  if (!std::isfinite(v)) return false;
  const bool okLo = loOpen ? v > lo : v >= lo;
  const bool okHi = hiOpen ? v < hi : v <= hi;
  return okLo && okHi;
}

std::string Range::describe() const {
  const bool hasLo = std::isfinite(lo), hasHi = std::isfinite(hi);
  if (hasLo && hasHi)
    return std::string("a number in ") + (loOpen ? "(" : "[") + shortNumber(lo) + ", " +
           shortNumber(hi) + (hiOpen ? ")" : "]");
  if (hasLo) return std::string("a number ") + (loOpen ? "> " : ">= ") + shortNumber(lo);
  if (hasHi) return std::string("a number ") + (hiOpen ? "< " : "<= ") + shortNumber(hi);
  return "a finite number";
}

YamlSection::YamlSection(YAML::Node node, std::string path) : node_(node), path_(std::move(path)) {
  if (node_.IsDefined() && !node_.IsNull() && !node_.IsMap())
    throw ConfigError("case.yaml: " + (path_.empty() ? std::string("<root>") : path_) + " = " +
                      YAML::Dump(node_) + ": must be a map of keys");
}

std::string YamlSection::keyPath(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

bool YamlSection::has(const std::string& key) const {
  return node_.IsMap() && node_[key].IsDefined() && !node_[key].IsNull();
}

std::vector<std::string> YamlSection::keys() const {
  std::vector<std::string> out;
  if (node_.IsMap())
    for (const auto& item : node_) out.push_back(item.first.as<std::string>());
  return out;
}

YAML::Node YamlSection::node(const std::string& key) const {
  if (!has(key)) fail(key, "is required but missing");
  return node_[key];
}

std::string YamlSection::valueText(const std::string& key) const {
  std::string dumped = YAML::Dump(node_[key]);
  for (auto& c : dumped)
    if (c == '\n') c = ' ';
  return dumped;
}

void YamlSection::fail(const std::string& key, const std::string& what) const {
  std::string msg = "case.yaml: " + keyPath(key);
  if (has(key)) msg += " = " + valueText(key);
  throw ConfigError(msg + ": " + what);
}

void YamlSection::allowOnly(const std::vector<std::string>& keys) const {
  if (!node_.IsMap()) return;
  for (const auto& item : node_) {
    const auto key = item.first.as<std::string>();
    bool known = false;
    for (const auto& k : keys) known = known || (k == key);
    if (!known)
      throw ConfigError("case.yaml: unknown key " + keyPath(key) + "; allowed here: " + joined(keys));
  }
}

YamlSection YamlSection::map(const std::string& key) const {
  auto n = node(key);
  if (!n.IsMap()) fail(key, "must be a map of keys");
  return YamlSection(n, keyPath(key));
}

std::vector<YamlSection> YamlSection::listOfMaps(const std::string& key) const {
  auto n = node(key);
  if (!n.IsSequence()) fail(key, "must be a list");
  std::vector<YamlSection> out;
  for (std::size_t i = 0; i < n.size(); ++i) {
    const auto itemPath = keyPath(key) + "[" + std::to_string(i) + "]";
    if (!n[i].IsMap()) throw ConfigError("case.yaml: " + itemPath + ": must be a map of keys");
    out.emplace_back(n[i], itemPath);
  }
  return out;
}

double YamlSection::number(const std::string& key, std::optional<double> fallback,
                           Range range) const {
  if (!has(key)) {
    if (fallback) return *fallback;
    fail(key, "is required but missing (" + range.describe() + ")");
  }
  double v = 0;
  try {
    v = node_[key].as<double>();
  } catch (const YAML::Exception&) {
    fail(key, "must be " + range.describe());
  }
  if (!range.contains(v)) fail(key, "must be " + range.describe());
  return v;
}

int YamlSection::integer(const std::string& key, std::optional<int> fallback, int lo, int hi) const {
  const std::string allowed =
      "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (!has(key)) {
    if (fallback) return *fallback;
    fail(key, "is required but missing (" + allowed + ")");
  }
  int v = 0;
  try {
    v = node_[key].as<int>();
  } catch (const YAML::Exception&) {
    fail(key, "must be " + allowed);
  }
  if (v < lo || v > hi) fail(key, "must be " + allowed);
  return v;
}

std::string YamlSection::word(const std::string& key, std::optional<std::string> fallback,
                              const std::vector<std::string>& allowed) const {
  const std::string v = text(key, fallback);
  for (const auto& a : allowed)
    if (a == v) return v;
  fail(key, "must be one of: " + joined(allowed));
}

std::string YamlSection::text(const std::string& key, std::optional<std::string> fallback) const {
  if (!has(key)) {
    if (fallback) return *fallback;
    fail(key, "is required but missing");
  }
  if (!node_[key].IsScalar()) fail(key, "must be a single word");
  return node_[key].as<std::string>();
}

Vec3 YamlSection::vec3(const std::string& key, std::optional<Vec3> fallback, Range range) const {
  if (!has(key)) {
    if (fallback) return *fallback;
    fail(key, "is required but missing (a list of 3 numbers)");
  }
  auto n = node_[key];
  if (!n.IsSequence() || n.size() != 3) fail(key, "must be a list of 3 numbers");
  Vec3 v;
  for (int c = 0; c < 3; ++c) {
    try {
      v[c] = n[c].as<double>();
    } catch (const YAML::Exception&) {
      fail(key, "must be a list of 3 numbers, each " + range.describe());
    }
    if (!range.contains(v[c])) fail(key, "each component must be " + range.describe());
  }
  return v;
}

std::vector<double> YamlSection::numbers(const std::string& key, std::size_t count,
                                         Range range) const {
  const std::string allowed =
      "a list of " + std::to_string(count) + " numbers, each " + range.describe();
  auto n = node(key);
  if (!n.IsSequence() || n.size() != count) fail(key, "must be " + allowed);
  std::vector<double> v(count);
  for (std::size_t c = 0; c < count; ++c) {
    try {
      v[c] = n[c].as<double>();
    } catch (const YAML::Exception&) {
      fail(key, "must be " + allowed);
    }
    if (!range.contains(v[c])) fail(key, "must be " + allowed);
  }
  return v;
}

std::array<int, 3> YamlSection::int3(const std::string& key, int lo, int hi) const {
  const std::string allowed = "a list of 3 integers in [" + std::to_string(lo) + ", " +
                              std::to_string(hi) + "]";
  auto n = node(key);
  if (!n.IsSequence() || n.size() != 3) fail(key, "must be " + allowed);
  std::array<int, 3> v{};
  for (int c = 0; c < 3; ++c) {
    try {
      v[c] = n[c].as<int>();
    } catch (const YAML::Exception&) {
      fail(key, "must be " + allowed);
    }
    if (v[c] < lo || v[c] > hi) fail(key, "must be " + allowed);
  }
  return v;
}

std::string YamlSection::singleKey(const std::vector<std::string>& allowed) const {
  if (!node_.IsMap() || node_.size() != 1)
    throw ConfigError("case.yaml: " + path_ + ": must have exactly one key, one of: " +
                      joined(allowed));
  const auto key = node_.begin()->first.as<std::string>();
  for (const auto& a : allowed)
    if (a == key) return key;
  throw ConfigError("case.yaml: unknown key " + keyPath(key) + "; allowed here: " + joined(allowed));
}

}  // namespace parcelflow::cfd
