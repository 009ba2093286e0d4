// case.yaml's coupling keys: defaults, and errors that name the key path, the value and what is allowed.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "coupling/run/case_reader.h"
#include "cfd/base/config_error.hpp"
#include "tests/unit/coupling/case_folder_error.hpp"

namespace pc = parcelflow::coupling;

namespace {

const char* kValid = R"(
liggghts: {script: bed.in, variables: {np: "8"}}
time: {end: 1.0, gas_step: 2.0e-4, dem_step: 2.0e-5}
mesh: {lengths: [0.02, 0.02, 0.1], cells: [5, 5, 25]}
)";

std::string errorOf(const std::string& extra_yaml) {
  try {
    pc::readCouplingSettings(YAML::Load(std::string(kValid) + extra_yaml));
  } catch (const parcelflow::cfd::ConfigError& e) {
    return e.what();
  }
  return "";
}

void expectMentions(const std::string& message, const std::vector<std::string>& parts) {
  EXPECT_FALSE(message.empty()) << "no error raised";
  for (const auto& part : parts) EXPECT_NE(message.find(part), std::string::npos) << message << "\nlacks: " << part;
}

}  // namespace

TEST(CaseReader, ReadsValuesAndDefaults) {
  const pc::CaseSettings s = pc::readCouplingSettings(YAML::Load(kValid));
  EXPECT_EQ(s.liggghts.script, "bed.in");
  ASSERT_EQ(s.liggghts.variables.size(), 1u);
  EXPECT_EQ(s.time.demStepsPerGasStep(), 10);
  EXPECT_EQ(s.coupling.drag, "WenYu");
  EXPECT_EQ(s.coupling.kernel.type, "gaussian");
  EXPECT_EQ(s.coupling.kernel.length_scale, "cell_volume");
  EXPECT_EQ(s.coupling.kernel.parcel_scale, 0.0);
  EXPECT_EQ(s.coupling.kernel.boundary, "truncate");
  EXPECT_EQ(s.coupling.kernel.smoothing_length, 0.0);
  EXPECT_FALSE(s.monitors.has_bed_pressure_drop);
}

TEST(CaseReader, ErrorsNameKeyValueAndAllowed) {
  expectMentions(errorOf("colling: {drag: WenYu}\n"), {"colling", "coupling"});
  expectMentions(errorOf("coupling: {drag: Stokes}\n"), {"coupling.drag", "Stokes", "WenYu", "Gidaspow"});
  expectMentions(errorOf("coupling: {kernel: {type: gaussian, radius: 9}}\n"), {"coupling.kernel.radius", "9"});
  expectMentions(errorOf("coupling: {kernel: {type: gaussian, length_scale: cube}}\n"),
                 {"coupling.kernel.length_scale", "cube", "cell_axes", "cell_volume"});
  expectMentions(errorOf("coupling: {kernel: {type: gaussian, parcel_scale: -1}}\n"),
                 {"coupling.kernel.parcel_scale", "-1", "[0, 4]"});
  expectMentions(errorOf("coupling: {kernel: {type: gaussian, boundary: mirror}}\n"),
                 {"coupling.kernel.boundary", "mirror", "truncate", "reflect"});
  expectMentions(errorOf("coupling: {kernel: {type: gaussian, smoothing_length: -0.002}}\n"),
                 {"coupling.kernel.smoothing_length", "-0.002"});
  expectMentions(errorOf("coupling: {gas_fraction_floor: 1.5}\n"), {"coupling.gas_fraction_floor", "1.5"});
  expectMentions(errorOf("monitors: {bed_pressure_drop: [0.05, 0.01]}\n"), {"monitors.bed_pressure_drop", "z_low < z_high"});
  expectMentions(errorOf("output: {monitor_interval: -1}\n"), {"output.monitor_interval", "-1"});
}

// A misspelt key is the unknown key it is (with its value and the closest allowed name), also when the key it
// stands for is required.
TEST(CaseReader, MisspeltKeysAreNamedWithTheClosestAllowedName) {
  const auto errorOfFile = [](const std::string& yaml) {
    try {
      pc::readCouplingSettings(YAML::Load(yaml));
    } catch (const parcelflow::cfd::ConfigError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string requiredStep =
      errorOfFile("liggghts: {script: bed.in}\ntime: {end: 1.0, gas_stp: 2.0e-4, dem_step: 2.0e-5}\n");
  expectMentions(requiredStep, {"case.yaml: unknown key time.gas_stp (value 2.0e-4) is not allowed here; did you "
                                "mean gas_step? allowed here: end, gas_step, dem_step"});
  EXPECT_EQ(requiredStep.find("required"), std::string::npos) << requiredStep;
  expectMentions(errorOfFile("liggghts: {scrpit: bed.in}\n"),
                 {"unknown key liggghts.scrpit (value bed.in)", "did you mean script?"});
  expectMentions(errorOf("coupling: {kernel: {type: gaussian, sharpnes: 2}}\n"),
                 {"unknown key coupling.kernel.sharpnes (value 2)", "did you mean sharpness?",
                  "allowed here: type, sharpness, radius, length_scale"});
  expectMentions(errorOf("output: {feilds_interval: 0.1, colour: red}\n"),
                 {"unknown keys output.feilds_interval (value 0.1; did you mean fields_interval?), output.colour "
                  "(value red) are not allowed here"});
  expectMentions(errorOf("monitor: {pressure_planes: [0.01]}\n"),
                 {"unknown key monitor (value ", "did you mean monitors?"});
}

TEST(CaseReader, GasStepMustBeAWholeNumberOfDemSteps) {
  const char* yaml = R"(
liggghts: {script: bed.in}
time: {end: 1.0, gas_step: 2.5e-4, dem_step: 1.0e-4}
)";
  try {
    pc::readCouplingSettings(YAML::Load(yaml));
    FAIL() << "no error raised";
  } catch (const parcelflow::cfd::ConfigError& e) {
    expectMentions(e.what(), {"time.gas_step", "2.5", "whole number of DEM steps"});
  }
}

TEST(CaseReader, TimeStepsThatMisleadAreRefused) {
  const auto timeError = [](const std::string& time) {
    try {
      pc::readCouplingSettings(YAML::Load("liggghts: {script: bed.in}\ntime: " + time + "\n"));
    } catch (const parcelflow::cfd::ConfigError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  expectMentions(timeError("{end: 1.0e-4, gas_step: 2.0e-4, dem_step: 2.0e-5}"), {"time.gas_step", "gas_step <= end"});
  // 2^32 DEM steps per gas step (an int would overflow to 0).
  expectMentions(timeError("{end: 1.0e6, gas_step: 85899.34592, dem_step: 2.0e-5}"),
                 {"time.gas_step", "4.29497e+09 DEM steps", "at most 1e6"});
  pc::TimeSettings t = pc::readCouplingSettings(YAML::Load(kValid)).time;
  pc::applyEndTime(t, 0.5);
  EXPECT_DOUBLE_EQ(t.end, 0.5);
  try {
    pc::applyEndTime(t, 1e-300);
    FAIL() << "no error raised";
  } catch (const parcelflow::cfd::ConfigError& e) {
    expectMentions(e.what(), {"--end = 1e-300", "at least one gas step"});
  }
  try {
    pc::applyEndTime(t, 0.0, 0.5);  // continuing a checkpoint at t = 0.5 s
    FAIL() << "no error raised";
  } catch (const parcelflow::cfd::ConfigError& e) {
    expectMentions(e.what(), {"time.end = 0.5", "after the checkpoint's time 0.5"});
  }
}

TEST(CaseReader, GuardsAndFloor) {
  const pc::CaseSettings s = pc::readCouplingSettings(YAML::Load(std::string(kValid) +
                                                                 "coupling: {guards: {max_cfl: 50}}\n"));
  EXPECT_DOUBLE_EQ(s.coupling.guards.max_cfl, 50.0);
  EXPECT_DOUBLE_EQ(s.coupling.guards.max_continuity_error, 1.0);
  EXPECT_DOUBLE_EQ(s.coupling.guards.max_parcel_loss, 0.1);
  expectMentions(errorOf("coupling: {guards: {max_parcel_loss: 0}}\n"), {"coupling.guards.max_parcel_loss", "(0, 1]"});
  expectMentions(errorOf("coupling: {guards: {max_cfll: 5}}\n"), {"coupling.guards.max_cfll"});
  expectMentions(errorOf("coupling: {gas_fraction_floor: 1.0e-300}\n"), {"coupling.gas_fraction_floor", "[0.01, 1)"});
}

TEST(CaseReader, ClassCollisionsTakeTheScriptsRestitutionAndFriction) {
  EXPECT_FALSE(pc::readCouplingSettings(YAML::Load(kValid)).coupling.class_collisions.enabled);
  const pc::CaseSettings s = pc::readCouplingSettings(
      YAML::Load(std::string(kValid) + "coupling: {class_collisions: {restitution: 0.97, friction: 0.1}}\n"));
  EXPECT_TRUE(s.coupling.class_collisions.enabled);
  EXPECT_DOUBLE_EQ(s.coupling.class_collisions.restitution, 0.97);
  EXPECT_DOUBLE_EQ(s.coupling.class_collisions.friction, 0.1);
  expectMentions(errorOf("coupling: {class_collisions: {restitution: 0.97}}\n"), {"coupling.class_collisions.friction"});
  expectMentions(errorOf("coupling: {class_collisions: {restitution: 1.5, friction: 0.1}}\n"),
                 {"coupling.class_collisions.restitution", "1.5", "[0, 1]"});
  expectMentions(errorOf("coupling: {class_collisions: {restitution: 0.9, friction: 0.1, e: 1}}\n"),
                 {"coupling.class_collisions.e"});
}

TEST(CaseReader, ACoupledRunTakesCutCells) {
  // parcels find their cut cells (issue 31, part 3): the coupled case reads with either wall representation
  const std::string yaml = "liggghts: {script: bed.in}\ntime: {end: 1.0, gas_step: 2.0e-4, dem_step: 2.0e-5}\n";
  for (const std::string walls : {"staircase", "cut_cells"})
    EXPECT_EQ(pc::test::caseFolderError(yaml + "mesh: {lengths: [0.02, 0.02, 0.1], cells: [5, 5, 25], walls: " +
                                        walls + "}\ngas: {density: 1.2, viscosity: 1.8e-5}\n"
                                        "boundaries: {zmax: {type: pressure_outlet}}\n"),
              "")
        << walls;
}
