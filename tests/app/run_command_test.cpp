// Runs `ecoforest run` as a user would.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_files.hpp"

namespace {

using eco::test::CommandResult;

CommandResult run(const std::string& arguments) {
  return eco::test::runCommand(std::string(ECOFOREST_EXE) + " " + arguments);
}

int lastYearIn(const std::string& stats) {
  const std::size_t start = stats.rfind('\n', stats.size() - 2) + 1;
  return std::stoi(stats.substr(start));
}

TEST(RunCommand, TheDefaultScenarioWritesARunFolder) {
  const auto dir = eco::test::freshDirectory("app_run");
  CommandResult r = run("run --years 12 --out " + dir.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("default: 12 years"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("year 12/12:"), std::string::npos) << "plain progress lines";
  EXPECT_EQ(r.output.find('\r'), std::string::npos);
  const nlohmann::json json = nlohmann::json::parse(eco::test::readFile(dir / "run.json"));
  EXPECT_EQ(json["status"], "complete");
  EXPECT_EQ(json["last_year"], 12);
  EXPECT_EQ(json["scenario"]["name"], "default");
  EXPECT_TRUE(json["final_counts"].contains("beech"));
  EXPECT_TRUE(std::filesystem::exists(dir / "trees" / "year_0010.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir / "trees" / "year_0012.csv"));

  // --resume with more years continues the same run.
  CommandResult more = run("run --resume --years 14 --out " + dir.string());
  ASSERT_EQ(more.exitCode, 0) << more.output;
  EXPECT_EQ(lastYearIn(eco::test::readFile(dir / "stats.csv")), 14);
}

TEST(RunCommand, CtrlCStopsAfterAYearWithCompleteFiles) {
  const auto dir = eco::test::freshDirectory("app_run_interrupt");
  CommandResult r =
      eco::test::runCommand("timeout --preserve-status -s INT 2 " + std::string(ECOFOREST_EXE) +
                            " run --years 400 --out " + dir.string());
  ASSERT_EQ(r.exitCode, 130) << r.output;
  EXPECT_NE(r.output.find("--resume"), std::string::npos) << r.output;
  const int stopped = lastYearIn(eco::test::readFile(dir / "stats.csv"));
  EXPECT_GT(stopped, 0);
  EXPECT_EQ(nlohmann::json::parse(eco::test::readFile(dir / "run.json"))["status"], "interrupted");
  CommandResult resumed =
      run("run --resume --years " + std::to_string(stopped + 1) + " --out " + dir.string());
  ASSERT_EQ(resumed.exitCode, 0) << resumed.output;
  EXPECT_EQ(lastYearIn(eco::test::readFile(dir / "stats.csv")), stopped + 1);
}

TEST(RunCommand, BadInputIsExitTwo) {
  const auto dir = eco::test::freshDirectory("app_run_bad");
  CommandResult none = run("run --resume --out " + dir.string());
  EXPECT_EQ(none.exitCode, 2);
  EXPECT_NE(none.output.find("checkpoint.bin: cannot open the checkpoint"), std::string::npos)
      << none.output;
  eco::test::writeFile(dir / "bad.toml",
                       "name = \"bad\"\n[terrain.generate]\nsize = 17\n"
                       "[[species]]\nfile = \"nothere.toml\"\n");
  CommandResult missing =
      run("run " + (dir / "bad.toml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_NE(missing.output.find("bad.toml:5: species[0].file: species file not found"),
            std::string::npos)
      << missing.output;
  EXPECT_EQ(run("run --years 0").exitCode, 2);
}

}  // namespace
