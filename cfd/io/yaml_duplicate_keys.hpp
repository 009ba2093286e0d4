#pragma once
// yaml-cpp's node API keeps the first of two equal keys in one map and hides the second, so a duplicated
// key in case.yaml would be ignored silently. This reads the file's parser events instead.
#include <string>

namespace parcelflow::cfd {

// Throws ConfigError naming the key path and both line numbers when a map of the YAML file `path` has
// a key twice. Syntax errors are left to the loader.
void checkNoDuplicateKeys(const std::string& path);

}  // namespace parcelflow::cfd
