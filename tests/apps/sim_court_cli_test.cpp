#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "apps/run_cli.hpp"
#include "temp_dir.hpp"

namespace ballsight::test {
namespace {

namespace fs = std::filesystem;

TEST(SimCourtCli, WritesImagesAndTruth) {
  const TempDir temp;
  const fs::path dir = temp / "out";
  const CliResult r = run_cli({"sim", "court", "--out", dir.string(), "--seed", "3", "--balls",
                               "25", "--width", "320", "--height", "180", "--chessboards", "1",
                               "--noise", "1", "--brightness", "1.1", "--no-shadow"});
  EXPECT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_TRUE(r.stderr_text.empty()) << r.stderr_text;
  for (const char* f : {"court_0000_cam0.png", "court_0000_cam3.png", "court_0000.json",
                        "cam2_board_00.png", "chessboards.json"}) {
    EXPECT_TRUE(fs::is_regular_file(dir / f)) << f;
  }
}

TEST(SimCourtCli, HelpNamesEveryOption) {
  const CliResult r = run_cli({"sim", "court", "--help"});
  EXPECT_EQ(r.exit_code, 0);
  for (const char* option :
       {"--out", "--seed", "--scenes", "--balls", "--width", "--height", "--chessboards", "--noise",
        "--brightness", "--light", "--no-shadow", "--no-wear", "--distractors"}) {
    EXPECT_NE(r.stdout_text.find(option), std::string::npos) << option;
  }
}

TEST(SimCourtCli, BadOptionsFailWithOneLine) {
  const TempDir temp;
  const fs::path dir = temp / "out";
  const std::vector<std::vector<std::string>> bad = {
      {"--out", dir.string(), "--balls", "-3"},     {"--out", dir.string(), "--balls", "201"},
      {"--out", dir.string(), "--width", "0"},      {"--out", dir.string(), "--height", "-720"},
      {"--out", dir.string(), "--seed", "abc"},     {"--out", dir.string(), "--seed", "-1"},
      {"--out", dir.string(), "--scenes", "-1"},    {"--out", dir.string(), "--noise", "-2"},
      {"--out", dir.string(), "--brightness", "0"}, {"--out", dir.string(), "--chessboards", "x"},
      {"--out", dir.string(), "--frobnicate"},      {"--seed", "1"},
      {"--out", dir.string(), "--light", "dusk"},
  };
  for (const auto& args : bad) {
    std::vector<std::string> command = {"sim", "court"};
    command.insert(command.end(), args.begin(), args.end());
    std::string shown;
    for (const auto& a : args) shown += a + " ";
    const CliResult r = run_cli(command);
    EXPECT_EQ(r.exit_code, 2) << shown << "\n" << r.stderr_text;
    EXPECT_EQ(line_count(r.stderr_text), 1) << shown << "\n" << r.stderr_text;
    EXPECT_EQ(r.stderr_text.rfind("ballsight: error: ", 0), 0u) << r.stderr_text;
  }
  EXPECT_FALSE(fs::exists(dir)) << "nothing written on bad options";
}

TEST(SimCourtCli, UnwritableOutputFailsWithOneLine) {
  const TempDir temp;
  const fs::path file = temp / "a_file";
  std::ofstream(file.string()) << "not a folder";
  const CliResult r = run_cli({"sim", "court", "--out", file.string(), "--scenes", "0"});
  EXPECT_EQ(r.exit_code, 2) << r.stderr_text;
  EXPECT_EQ(line_count(r.stderr_text), 1) << r.stderr_text;
}

}  // namespace
}  // namespace ballsight::test
