#include "cfd/io/yaml_duplicate_keys.hpp"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/yaml.h>

#include <fstream>
#include <map>
#include <vector>

#include "cfd/base/config_error.hpp"

namespace parcelflow::cfd {

namespace {

// Tracks, per open map, the keys seen and their lines; a map alternates key, value, key, value.
class DuplicateKeyFinder : public YAML::EventHandler {
 public:
  explicit DuplicateKeyFinder(std::string file) : file_(std::move(file)) {}

  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t) override { scalar(mark, "~"); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override { scalar(mark, "*alias"); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t, const std::string& value) override {
    scalar(mark, value);
  }
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    open(false);
  }
  void OnSequenceEnd() override { close(); }
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    open(true);
  }
  void OnMapEnd() override { close(); }

 private:
  struct Frame {
    bool is_map = false;
    bool is_key = false;  // a map or list used as a key (complex key)
    bool expect_key = true;
    std::string path, key;
    int items = 0;
    std::map<std::string, int> lines;  // key -> line (1-based)
  };

  void scalar(const YAML::Mark& mark, const std::string& value) {
    if (stack_.empty() || !stack_.back().is_map || !stack_.back().expect_key) {
      valueDone();
      return;
    }
    Frame& f = stack_.back();
    const std::string path = f.path.empty() ? value : f.path + "." + value;
    const auto [it, inserted] = f.lines.emplace(value, mark.line + 1);
    if (!inserted)
      throw ConfigError(file_ + ": " + path + " is given twice, on lines " + std::to_string(it->second) + " and " +
                        std::to_string(mark.line + 1) + "; allowed is each key once per map (the YAML reader would "
                        "use the first and ignore the second)");
    f.key = value;
    f.expect_key = false;
  }
  void open(bool is_map) {
    Frame child;
    child.is_map = is_map;
    if (!stack_.empty()) {
      const Frame& parent = stack_.back();
      child.is_key = parent.is_map && parent.expect_key;
      child.path = parent.is_map ? (parent.path.empty() ? parent.key : parent.path + "." + parent.key)
                                 : parent.path + "[" + std::to_string(parent.items) + "]";
    }
    stack_.push_back(child);
  }
  void close() {
    const bool was_key = stack_.back().is_key;
    stack_.pop_back();
    if (was_key) stack_.back().expect_key = false;
    else valueDone();
  }
  // A value (scalar or whole node) ended: the parent map expects a key next, a sequence its next item.
  void valueDone() {
    if (stack_.empty()) return;
    Frame& f = stack_.back();
    if (f.is_map) f.expect_key = true;
    else ++f.items;
  }

  std::string file_;
  std::vector<Frame> stack_;
};

}  // namespace

void checkNoDuplicateKeys(const std::string& path) {
  std::ifstream in(path);
  if (!in) return;
  DuplicateKeyFinder finder(path);
  try {
    YAML::Parser parser(in);
    while (parser.HandleNextDocument(finder)) {
    }
  } catch (const YAML::Exception&) {
    // The loader reports syntax errors with its own message.
  }
}

}  // namespace parcelflow::cfd
