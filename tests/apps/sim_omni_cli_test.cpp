// `ballsight sim omni` end to end: files written, and bad input ends with one line on stderr and
// a non-zero exit status, never a crash.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

struct CliRun {
  int exit_status = -1;
  bool signalled = false;
  std::string out;
  std::string err;
};

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

class SimOmniCli : public testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        fs::temp_directory_path() / ("ballsight_sim_omni_cli_" + std::to_string(::getpid()) + "_" +
                                     testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  CliRun run(const std::string& args) const {
    const fs::path out = dir_ / "stdout.txt";
    const fs::path err = dir_ / "stderr.txt";
    const std::string command = std::string("'") + BALLSIGHT_CLI + "' " + args + " >'" +
                                out.string() + "' 2>'" + err.string() + "'";
    const int status = std::system(command.c_str());
    CliRun r;
    r.signalled = WIFSIGNALED(status);
    r.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
  }

  fs::path dir_;
};

TEST_F(SimOmniCli, WritesOnePngAndOneTruthPerFrame) {
  const fs::path out = dir_ / "scenes";
  const CliRun r = run("sim omni --out '" + out.string() + "' --seed 3 --frames 2 --noise 2");
  ASSERT_EQ(r.exit_status, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  for (const char* name : {"omni_0000.png", "omni_0000.json", "omni_0001.png", "omni_0001.json"}) {
    EXPECT_GT(fs::file_size(out / name), 1000u) << name;
  }
  EXPECT_FALSE(fs::exists(out / "omni_0002.png"));
  const std::string truth = slurp(out / "omni_0001.json");
  EXPECT_NE(truth.find("\"format\": \"ballsight.sim.omni.truth\""), std::string::npos);
  EXPECT_NE(truth.find("\"silhouette_centroid_px\""), std::string::npos);

  // Same seed, same bytes.
  const fs::path again = dir_ / "again";
  ASSERT_EQ(
      run("sim omni --out '" + again.string() + "' --seed 3 --frames 2 --noise 2").exit_status, 0);
  EXPECT_EQ(slurp(out / "omni_0001.png"), slurp(again / "omni_0001.png"));
  EXPECT_EQ(slurp(out / "omni_0001.json"), slurp(again / "omni_0001.json"));
}

// A traced mirror's truth names its kind and its profile (docs/sim-omni.md).
TEST_F(SimOmniCli, ATracedMirrorIsInTheTruth) {
  const fs::path out = dir_ / "table";
  ASSERT_EQ(run("sim omni --out '" + out.string() + "' --frames 1 --mirror table").exit_status, 0);
  const std::string truth = slurp(out / "omni_0000.json");
  EXPECT_NE(truth.find("\"kind\": \"table\""), std::string::npos);
  EXPECT_NE(truth.find("\"table_m\""), std::string::npos);
}

TEST_F(SimOmniCli, BadInputEndsWithOneLineAndNonZeroStatus) {
  const std::string out = "--out '" + (dir_ / "bad").string() + "' ";
  const std::string cases[] = {
      out + "--frames -1",
      out + "--frames 0",
      out + "--tilt-deg 45",
      out + "--seed abc",
      out + "--seed -5",
      out + "--center-offset-px 3",
      out + "--center-offset-px 80,0",
      out + "--noise -1",
      out + "--blur 1e9",
      out + "--brightness 0",
      out + "--bogus 1",
      out + "--mirror parabolic",
      "--frames 2",                                    // missing --out
      "--out '" + (dir_ / "file.txt").string() + "'",  // not a folder
  };
  std::ofstream(dir_ / "file.txt") << "x";
  for (const std::string& args : cases) {
    SCOPED_TRACE(args);
    const CliRun r = run("sim omni " + args);
    EXPECT_FALSE(r.signalled);
    EXPECT_NE(r.exit_status, 0);
    EXPECT_LT(r.exit_status, 128);  // an exit, not a crash
    ASSERT_FALSE(r.err.empty());
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;  // exactly one line
    EXPECT_EQ(r.err.rfind("ballsight: error: ", 0), 0u) << r.err;
    EXPECT_EQ(r.err.find("terminate"), std::string::npos) << r.err;
  }
  EXPECT_FALSE(fs::exists(dir_ / "bad"));  // options are checked before anything is written
}

TEST_F(SimOmniCli, HelpDescribesEveryOption) {
  const CliRun r = run("sim omni --help");
  ASSERT_EQ(r.exit_status, 0);
  for (const char* option :
       {"--out", "--seed", "--frames", "--tilt-deg", "--tilt-azimuth-deg", "--center-offset-px",
        "--noise", "--blur", "--brightness", "--no-markers", "--mirror"}) {
    EXPECT_NE(r.out.find(option), std::string::npos) << option;
  }
}

}  // namespace
