#include "cfd/io/yaml_section.hpp"

#include <algorithm>
#include <cmath>

#include "cfd/base/config_error.hpp"
#include "cfd/base/internal_error.hpp"
#include "cfd/base/number_text.hpp"

namespace parcelflow::cfd {

namespace {
std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

// The fewest edits (insert, delete or replace a letter, swap two neighbours) that turn a into b.
std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

// The allowed name a misspelt key most likely meant: the nearest one, if at most a third of its letters (at
// least one) need an edit; "" if none is that near.
std::string closestName(const std::string& key, const std::vector<std::string>& allowed) {
  std::string best;
  std::size_t nearest = 0;
  for (const auto& name : allowed) {
    const std::size_t distance = editDistance(key, name);
    if (distance <= std::max<std::size_t>(1, name.size() / 3) && (best.empty() || distance < nearest)) {
      best = name;
      nearest = distance;
    }
  }
  return best;
}

// A value as one short line (a misspelt section's whole map would otherwise fill the message).
std::string shortValue(std::string text) {
  constexpr std::size_t kMaxLength = 60;
  return text.size() > kMaxLength ? text.substr(0, kMaxLength - 3) + "..." : text;
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

void YamlSection::allowAnyKeys() const { keysChecked_ = true; }

bool YamlSection::present(const std::string& key) const {
  PARCELFLOW_ASSERT(keysChecked_, "case.yaml: " + keyPath(key) + " is read before the keys of " +
                                      (path_.empty() ? std::string("<root>") : path_) + " were checked (allowOnly)");
  return has(key);
}

YAML::Node YamlSection::node(const std::string& key) const {
  if (!present(key)) fail(key, "is required but missing");
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

void YamlSection::failUnknown(const std::vector<std::string>& unknown, const std::vector<std::string>& allowed) const {
  const bool one = unknown.size() == 1;
  std::string named, guess;
  for (const auto& key : unknown) {
    const std::string closest = closestName(key, allowed);
    guess = closest.empty() ? "" : "did you mean " + closest + "?";
    named += (named.empty() ? "" : ", ") + keyPath(key) + " (value " + shortValue(valueText(key)) +
             (one || guess.empty() ? "" : "; " + guess) + ")";
  }
  throw ConfigError("case.yaml: unknown key" + std::string(one ? " " : "s ") + named +
                    (one ? " is" : " are") + " not allowed here; " + (one && !guess.empty() ? guess + " " : "") +
                    "allowed here: " + joined(allowed));
}

void YamlSection::allowOnly(const std::vector<std::string>& keys) const {
  keysChecked_ = true;
  std::vector<std::string> unknown;
  for (const auto& key : this->keys())
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) unknown.push_back(key);
  if (!unknown.empty()) failUnknown(unknown, keys);
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
  if (!present(key)) {
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
  if (!present(key)) {
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
  if (!present(key)) {
    if (fallback) return *fallback;
    fail(key, "is required but missing");
  }
  if (!node_[key].IsScalar()) fail(key, "must be a single word");
  return node_[key].as<std::string>();
}

Vec3 YamlSection::vec3(const std::string& key, std::optional<Vec3> fallback, Range range) const {
  if (!present(key)) {
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
  keysChecked_ = true;
  const auto key = node_.begin()->first.as<std::string>();
  if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) failUnknown({key}, allowed);
  return key;
}

}  // namespace parcelflow::cfd
