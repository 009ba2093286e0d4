#include "script_variables.h"

#include <fstream>
#include <regex>
#include <set>

#include "cfd/config_error.hpp"

namespace parcelflow::coupling {

namespace {

struct Reference {
  std::string name, file;
  int line = 0;
};

const std::regex kDefinition(R"((?:^|[\s"'])variable\s+([A-Za-z0-9_]+))");
const std::regex kReference(R"(\$\{([A-Za-z0-9_]+)\}|\$([A-Za-z0-9_]))");
const std::regex kInclude(R"(^\s*include\s+(\S+)\s*$)");

// A line without its comment (LIGGGHTS: '#' outside quotes starts one).
std::string withoutComment(const std::string& line) {
  char quote = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (quote) {
      if (line[i] == quote) quote = 0;
    } else if (line[i] == '"' || line[i] == '\'') {
      quote = line[i];
    } else if (line[i] == '#') {
      return line.substr(0, i);
    }
  }
  return line;
}

void scan(const std::string& folder, const std::string& file, int depth, std::set<std::string>& defined,
          std::vector<Reference>& used) {
  std::ifstream in(folder + "/" + file);
  if (!in || depth > 8) return;  // LIGGGHTS reports a missing include itself
  std::string raw, line;
  int number = 0, first = 0;
  while (std::getline(in, raw)) {
    ++number;
    if (line.empty()) first = number;
    line += withoutComment(raw);
    const auto last = line.find_last_not_of(" \t\r");
    if (last != std::string::npos && line[last] == '&') {  // continued on the next line
      line.erase(last);
      continue;
    }
    for (std::sregex_iterator m(line.begin(), line.end(), kDefinition), end; m != end; ++m) defined.insert((*m)[1]);
    for (std::sregex_iterator m(line.begin(), line.end(), kReference), end; m != end; ++m)
      used.push_back({(*m)[1].matched ? (*m)[1].str() : (*m)[2].str(), file, first});
    std::smatch include;
    if (std::regex_match(line, include, kInclude) && include[1].str().find('$') == std::string::npos)
      scan(folder, include[1], depth + 1, defined, used);
    line.clear();
  }
}

}  // namespace

void checkScriptVariables(const std::string& folder, const std::string& script,
                          const std::vector<std::string>& passed) {
  std::set<std::string> defined(passed.begin(), passed.end());
  std::vector<Reference> used;
  scan(folder, script, 0, defined, used);
  for (const Reference& r : used)
    if (!defined.count(r.name))
      throw cfd::ConfigError("liggghts.script: " + r.file + " line " + std::to_string(r.line) + " uses the variable " +
                             r.name + ", which neither a `variable " + r.name +
                             " ...` command of the script nor liggghts.variables defines (parcelflow itself passes "
                             "dem_step, restarting and restart_file)");
}

}  // namespace parcelflow::coupling
