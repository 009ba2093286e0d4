#include "coupling/dem/script_variables.h"

#include <cctype>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
#include <set>

#include "cfd/base/config_error.hpp"

namespace parcelflow::coupling {

namespace {

struct Place {
  std::string file;
  int line = 0;
  long order = 0;  // position in the order LIGGGHTS reads the lines, includes expanded where they stand
};

struct Reference {
  std::string name;
  Place place;
  bool conditional = false;  // inside the quoted commands of an `if`: substituted only if that branch runs
};

// A reference that is the whole argument of a keyword LIGGGHTS reads with atoi or atoll, which take the
// leading digits and ignore the rest: "1e5" parcels would be 1 parcel, without a word.
struct WholeNumberUse {
  std::string name, keyword;
  Place place;
  long long largest = 0;
};

struct Scan {
  std::map<std::string, Place> first_definition;
  std::vector<Reference> used;
  std::vector<WholeNumberUse> whole_numbers;
  std::map<std::pair<std::string, std::string>, long> labels;  // (file, label) -> order
  std::vector<std::pair<std::pair<std::string, std::string>, long>> jumps;
  long order = 0;
};

const std::regex kDefinition(R"((?:^|[\s"'])variable\s+([A-Za-z0-9_]+))");
const std::regex kReference(R"(\$\{([A-Za-z0-9_]+)\}|\$([A-Za-z0-9_]))");
const std::regex kInclude(R"(^\s*include\s+(\S+)\s*$)");
const std::regex kLabel(R"(^\s*label\s+(\S+))");
const std::regex kJump(R"(^\s*jump\s+(\S+)(?:\s+(\S+))?)");
const std::regex kIf(R"(^\s*if\s)");
// Arguments LIGGGHTS reads with atoi / atoll (LIGGGHTS 3.8 sources): `run N start M stop K` (also as the
// command of an `if` branch), and the counts of the fix insert styles
const std::regex kRunSteps(R"((?:^\s*|["'])run\s+$)");
const std::regex kRunCommand(R"((?:^\s*|["'])run\s)");
const std::regex kRunBound(R"(\s(?:start|stop)\s+$)");
const std::regex kInsertFix(R"(^\s*fix\s+\S+\s+\S+\s+insert/)");
const std::regex kInsertCount(R"(\s(particles_in_region|maxattempt|insert_every|every|start)\s+$)");

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

// whether position `at` of `line` lies between quotes
bool quoted(const std::string& line, std::size_t at) {
  char quote = 0;
  for (std::size_t i = 0; i < at; ++i)
    if (quote ? line[i] == quote : (line[i] == '"' || line[i] == '\'')) quote = quote ? 0 : line[i];
  return quote != 0;
}

void scanLine(const std::string& folder, const std::string& file, const std::string& line, int number, int depth,
              Scan& s);

void scanFile(const std::string& folder, const std::string& file, int depth, Scan& s) {
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
    scanLine(folder, file, line, first, depth, s);
    line.clear();
  }
}

void scanLine(const std::string& folder, const std::string& file, const std::string& line, int number, int depth,
              Scan& s) {
  const Place here{file, number, ++s.order};
  const bool branch = std::regex_search(line, kIf);
  for (std::sregex_iterator m(line.begin(), line.end(), kReference), end; m != end; ++m) {
    const std::string name = (*m)[1].matched ? (*m)[1].str() : (*m)[2].str();
    const auto at = static_cast<std::size_t>(m->position());
    s.used.push_back({name, here, branch && quoted(line, at)});
    const std::size_t after = at + static_cast<std::size_t>(m->length());
    if (after != line.size() && !std::isspace(static_cast<unsigned char>(line[after]))) continue;
    const std::string before = line.substr(0, at);
    std::smatch keyword;
    if (std::regex_search(line, kInsertFix) && std::regex_search(before, keyword, kInsertCount))
      s.whole_numbers.push_back({name, keyword[1], here, INT_MAX});
    else if (std::regex_search(before, kRunSteps) ||
             (std::regex_search(before, kRunCommand) && std::regex_search(before, kRunBound)))
      s.whole_numbers.push_back({name, "run", here, LLONG_MAX});
  }
  for (std::sregex_iterator m(line.begin(), line.end(), kDefinition), end; m != end; ++m)
    s.first_definition.emplace((*m)[1], here);
  std::smatch match;
  if (std::regex_search(line, match, kLabel)) s.labels[{file, match[1]}] = here.order;
  if (std::regex_search(line, match, kJump) && match[2].matched)
    s.jumps.push_back({{match[1] == "SELF" ? file : match[1].str(), match[2]}, here.order});
  if (std::regex_match(line, match, kInclude) && match[1].str().find('$') == std::string::npos)
    scanFile(folder, match[1], depth + 1, s);
}

std::string where(const Place& p) { return p.file + " line " + std::to_string(p.line); }

bool wholeNumber(const std::string& text, long long largest) {
  if (!std::regex_match(text, std::regex(R"(\s*[+-]?[0-9]+\s*)"))) return false;
  errno = 0;
  const long long value = std::strtoll(text.c_str(), nullptr, 10);
  return errno == 0 && value <= largest && value >= -largest;
}

}  // namespace

void checkScriptVariables(const std::string& folder, const std::string& script,
                          const std::vector<std::string>& passed,
                          const std::vector<std::pair<std::string, std::string>>& values) {
  Scan s;
  scanFile(folder, script, 0, s);
  for (const WholeNumberUse& use : s.whole_numbers)
    for (const auto& [name, value] : values)
      if (name == use.name && !wholeNumber(value, use.largest))
        throw cfd::ConfigError("liggghts.variables." + name, value,
                               "a whole number written in digits, at most " + std::to_string(use.largest) + ": " +
                                   where(use.place) + " gives it to `" + use.keyword +
                                   "`, which LIGGGHTS reads with atoi or atoll: they take the leading digits and "
                                   "drop the rest");
  const std::set<std::string> outside(passed.begin(), passed.end());
  // A jump back to an earlier label may run a definition before a use that precedes it in the file.
  bool backward_jump = false;
  for (const auto& [label, order] : s.jumps) {
    const auto target = s.labels.find(label);
    backward_jump = backward_jump || (target != s.labels.end() && target->second < order);
  }
  for (const Reference& r : s.used) {
    if (outside.count(r.name)) continue;
    const auto definition = s.first_definition.find(r.name);
    if (definition == s.first_definition.end())
      throw cfd::ConfigError("liggghts.script: " + where(r.place) + " uses the variable " + r.name +
                             ", which neither a `variable " + r.name +
                             " ...` command of the script nor liggghts.variables defines (parcelflow itself passes "
                             "dem_step, restarting and restart_file)");
    if (!backward_jump && !r.conditional && definition->second.order > r.place.order)
      throw cfd::ConfigError("liggghts.script: " + where(r.place) + " uses the variable " + r.name +
                             " before its definition in " + where(definition->second) +
                             " (LIGGGHTS reads the script in order; define it earlier or in liggghts.variables)");
  }
}

}  // namespace parcelflow::coupling
