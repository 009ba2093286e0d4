// Small pieces shared by parcelflow's fix styles.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

namespace parcelflow::plugins {

// The arguments of `fix ID group style ...` after the style name.
std::vector<std::string> style_arguments(int narg, char** arg);

// A fix's global restart state, written by rank 0 (`me`) as LIGGGHTS expects: its size in bytes, then the values.
void write_global_state(int me, FILE* fp, const std::vector<double>& values);

}  // namespace parcelflow::plugins
