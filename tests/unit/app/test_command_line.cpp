#include <gtest/gtest.h>

#include "coupling/app/command_line.h"

namespace pc = parcelflow::coupling;

namespace {

std::string usageErrorOf(const std::vector<std::string>& args) {
  try {
    pc::parseCommandLine(args);
  } catch (const pc::UsageError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(CommandLine, DemWithVariablesAndLog) {
  const auto cl = pc::parseCommandLine({"dem", "in.bed", "-var", "np", "8", "-log", "run/log", "-var", "u", "1.1"});
  EXPECT_EQ(cl.action, pc::CommandLine::Action::dem);
  EXPECT_EQ(cl.script, "in.bed");
  ASSERT_EQ(cl.vars.size(), 2u);
  EXPECT_EQ(cl.vars[0], std::make_pair(std::string("np"), std::string("8")));
  EXPECT_EQ(cl.vars[1], std::make_pair(std::string("u"), std::string("1.1")));
  EXPECT_EQ(cl.log_file, "run/log");
}

TEST(CommandLine, RunWithOutputFolder) {
  const auto cl = pc::parseCommandLine({"run", "cases/bed", "--output", "/tmp/out"});
  EXPECT_EQ(cl.action, pc::CommandLine::Action::run);
  EXPECT_EQ(cl.case_folder, "cases/bed");
  EXPECT_EQ(cl.output_folder, "/tmp/out");
  EXPECT_NE(usageErrorOf({"run"}).find("needs a case folder"), std::string::npos);
  EXPECT_NE(usageErrorOf({"run", "c", "--output"}).find("--output DIR"), std::string::npos);
  EXPECT_NE(usageErrorOf({"run", "c", "-np", "2"}).find("unknown option '-np'"), std::string::npos);
}

TEST(CommandLine, RunWithEndTime) {
  const auto cl = pc::parseCommandLine({"run", "cases/bed", "--end", "2.5", "--output", "o"});
  EXPECT_DOUBLE_EQ(cl.end_time, 2.5);
  EXPECT_EQ(cl.output_folder, "o");
  EXPECT_DOUBLE_EQ(pc::parseCommandLine({"run", "cases/bed"}).end_time, 0.0);
  for (const char* bad : {"0", "-1", "2s", "nan", "inf", ""})
    EXPECT_NE(usageErrorOf({"run", "c", "--end", bad}).find("option '--end' got '" + std::string(bad) + "'"),
              std::string::npos)
        << bad;
  EXPECT_NE(usageErrorOf({"run", "c", "--end"}).find("--end SECONDS"), std::string::npos);
}

TEST(CommandLine, HelpAndVersion) {
  EXPECT_EQ(pc::parseCommandLine({"--help"}).action, pc::CommandLine::Action::help);
  EXPECT_EQ(pc::parseCommandLine({"--version"}).action, pc::CommandLine::Action::version);
}

TEST(CommandLine, ErrorsNameTheArgumentAndWhatIsAllowed) {
  EXPECT_NE(usageErrorOf({}).find("no command"), std::string::npos);
  EXPECT_NE(usageErrorOf({"simulate"}).find("unknown command 'simulate'; allowed: run, dem"), std::string::npos);
  EXPECT_NE(usageErrorOf({"dem"}).find("needs a LIGGGHTS input script"), std::string::npos);
  EXPECT_NE(usageErrorOf({"dem", "-var"}).find("needs a LIGGGHTS input script"), std::string::npos);
  EXPECT_NE(usageErrorOf({"dem", "in.x", "-var", "a"}).find("-var NAME VALUE"), std::string::npos);
  EXPECT_NE(usageErrorOf({"dem", "in.x", "-log"}).find("-log FILE"), std::string::npos);
  EXPECT_NE(usageErrorOf({"dem", "in.x", "-echo"}).find("unknown option '-echo'"), std::string::npos);
  EXPECT_NE(usageErrorOf({"--version", "x"}).find("takes no arguments"), std::string::npos);
  EXPECT_NE(usageErrorOf({"run", "case", "--output", ""}).find("--output DIR (a non-empty path)"), std::string::npos);
  EXPECT_NE(usageErrorOf({"run", "case", "--end", "1", "--end", "2"}).find("option '--end' is given twice"),
            std::string::npos);
  EXPECT_NE(usageErrorOf({"run", "case", "--output", "a", "--end", "1", "--output", "b"})
                .find("option '--output' is given twice"),
            std::string::npos);
}
