#pragma once
// The ConfigError of readCase on a temporary case folder holding `yaml` as case.yaml and an empty-ish
// bed.in (checks that need the gas section run only in readCase); "" when it reads. The folder is removed.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "coupling/run/case_reader.h"
#include "cfd/base/config_error.hpp"

namespace parcelflow::coupling::test {

inline std::string caseFolderError(const std::string& yaml) {
  namespace fs = std::filesystem;
  const fs::path folder = fs::temp_directory_path() / ("parcelflow_case_reader_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  std::ofstream(folder / "case.yaml") << yaml;
  std::ofstream(folder / "bed.in") << "# empty\n";
  std::string message;
  try {
    readCase(folder.string());
  } catch (const parcelflow::cfd::ConfigError& e) {
    message = e.what();
  }
  fs::remove_all(folder);
  return message;
}

}  // namespace parcelflow::coupling::test
