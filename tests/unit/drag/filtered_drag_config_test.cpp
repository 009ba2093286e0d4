// case.yaml's coupling.filtered_drag (coupling/run/case_reader.cpp): required by the filtered law, refused
// with any other, range-checked; errors name the key, the value and what is allowed.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "coupling/run/case_reader.h"
#include "cfd/base/config_error.hpp"
#include "tests/unit/coupling/case_folder_error.hpp"

namespace pc = parcelflow::coupling;

namespace {

const char* kCase = R"(
liggghts: {script: bed.in}
time: {end: 1.0, gas_step: 2.0e-4, dem_step: 2.0e-5}
mesh: {lengths: [0.02, 0.02, 0.1], cells: [5, 5, 25]}
)";

std::string couplingError(const std::string& coupling) {
  try {
    pc::readCouplingSettings(YAML::Load(std::string(kCase) + "coupling: " + coupling + "\n"));
  } catch (const parcelflow::cfd::ConfigError& e) {
    return e.what();
  }
  return "";
}

// readCase on a folder holding this case.yaml (the gas checks need the gas section).
std::string caseError(const std::string& yaml) {
  return pc::test::caseFolderError(std::string(kCase) + yaml + "boundaries: {zmax: {type: pressure_outlet}}\n");
}

void expectMentions(const std::string& message, const std::vector<std::string>& parts) {
  EXPECT_FALSE(message.empty()) << "no error raised";
  for (const auto& part : parts) EXPECT_NE(message.find(part), std::string::npos) << message << "\nlacks: " << part;
}

}  // namespace

TEST(FilteredDragConfig, ReadsTheParticleDensity) {
  const pc::CaseSettings s = pc::readCouplingSettings(YAML::Load(
      std::string(kCase) + "coupling: {drag: RadlSundaresanFilteredBVK, filtered_drag: {particle_density: 1500}}\n"));
  EXPECT_EQ(s.coupling.drag, "RadlSundaresanFilteredBVK");
  EXPECT_EQ(s.coupling.filtered_drag.particle_density, 1500.0);
  EXPECT_EQ(s.coupling.filtered_drag.filter_cells, 1.0);  // the cell, unless given
  const pc::CaseSettings wide = pc::readCouplingSettings(YAML::Load(
      std::string(kCase) + "coupling: {drag: RadlSundaresanFilteredBVK, filtered_drag: {particle_density: 1500, "
                           "filter_cells: 2}}\n"));
  EXPECT_EQ(wide.coupling.filtered_drag.filter_cells, 2.0);
  EXPECT_EQ(caseError("coupling: {drag: RadlSundaresanFilteredBVK, filtered_drag: {particle_density: 1500}}\n"
                      "gas: {density: 1.2, viscosity: 1.8e-5, gravity: [0, 0, -9.81]}\n"),
            "");
}

TEST(FilteredDragConfig, RequiredByTheFilteredLaw) {
  expectMentions(couplingError("{drag: RadlSundaresanFilteredBVK}"),
                 {"coupling.filtered_drag", "required", "RadlSundaresanFilteredBVK", "particle_density"});
  expectMentions(couplingError("{drag: RadlSundaresanFilteredBVK, filtered_drag: {}}"),
                 {"coupling.filtered_drag.particle_density", "required"});
}

TEST(FilteredDragConfig, RefusedWithAnyOtherLaw) {
  expectMentions(couplingError("{drag: WenYu, filtered_drag: {particle_density: 1500}}"),
                 {"coupling.filtered_drag", "only read by coupling.drag: RadlSundaresanFilteredBVK", "WenYu"});
  expectMentions(couplingError("{filtered_drag: {particle_density: 1500}}"),  // the default law, WenYu
                 {"coupling.filtered_drag", "WenYu"});
}

TEST(FilteredDragConfig, ValuesAreRangeChecked) {
  expectMentions(couplingError("{drag: RadlSundaresanFilteredBVK, filtered_drag: {particle_density: -5}}"),
                 {"coupling.filtered_drag.particle_density", "-5", "> 0"});
  expectMentions(couplingError("{drag: RadlSundaresanFilteredBVK, filtered_drag: {particle_density: heavy}}"),
                 {"coupling.filtered_drag.particle_density", "heavy"});
  expectMentions(couplingError("{drag: RadlSundaresanFilteredBVK, filtered_drag: {particle_density: 1500, "
                               "filter_size: 0.1}}"),
                 {"coupling.filtered_drag.filter_size", "particle_density"});
  expectMentions(couplingError("{drag: RadlSundaresanFilteredBVK, filtered_drag: {particle_density: 1500, "
                               "filter_cells: 0.5}}"),
                 {"coupling.filtered_drag.filter_cells", "0.5", "[1, 10]"});
  // particles lighter than the gas have no terminal velocity; without gravity there is no length scale
  expectMentions(caseError("coupling: {drag: RadlSundaresanFilteredBVK, filtered_drag: {particle_density: 1.0}}\n"
                           "gas: {density: 1.2, viscosity: 1.8e-5}\n"),
                 {"coupling.filtered_drag.particle_density = 1", "> gas.density = 1.2"});
  expectMentions(caseError("coupling: {drag: RadlSundaresanFilteredBVK, filtered_drag: {particle_density: 1500}}\n"
                           "gas: {density: 1.2, viscosity: 1.8e-5, gravity: [0, 0, 0]}\n"),
                 {"gas.gravity = [0, 0, 0]", "non-zero", "RadlSundaresanFilteredBVK"});
}
