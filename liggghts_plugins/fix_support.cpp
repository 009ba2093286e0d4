#include "liggghts_plugins/fix_support.h"

namespace parcelflow::plugins {

std::vector<std::string> style_arguments(int narg, char** arg)
{
  std::vector<std::string> args;
  for (int i = 3; i < narg; ++i) args.emplace_back(arg[i]);
  return args;
}

void write_global_state(int me, FILE* fp, const std::vector<double>& values)
{
  if (me != 0) return;
  const int size = static_cast<int>(values.size() * sizeof(double));
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(values.data(), sizeof(double), values.size(), fp);
}

}  // namespace parcelflow::plugins
