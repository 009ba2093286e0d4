// LIGGGHTS stops on an undefined variable without naming it. Before it starts, this scans the case's
// script, and the files it `include`s by a plain name, for ${name} and $x references and checks that each
// name is defined by a `variable` command somewhere in those files (also inside an `if`'s quoted
// commands) or passed from outside (liggghts.variables and parcelflow's own), and that a reference outside an
// `if`'s quoted commands does not come before the first definition in the order LIGGGHTS reads the lines
// (includes expanded where they stand; not checked when a `jump` goes back to an earlier label, since a
// loop may define a variable on its first pass). Branches and forward jumps are not followed.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace parcelflow::coupling {

// `script` is opened from `folder` (LIGGGHTS runs there); throws cfd::ConfigError naming the variable,
// the file and the line of its first reference. Also refuses a value of `values` (liggghts.variables) that is
// not a whole number in digits where the script gives it to `run` or to a fix insert keyword that LIGGGHTS
// reads with atoi (`particles_in_region`, `maxattempt`, `insert_every`, `every`, `start`).
void checkScriptVariables(const std::string& folder, const std::string& script,
                          const std::vector<std::string>& passed,
                          const std::vector<std::pair<std::string, std::string>>& values);

}  // namespace parcelflow::coupling
