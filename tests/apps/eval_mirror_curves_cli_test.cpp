// `ballsight eval mirror-curves`: the simulator's mirrors beside the real sets, as a table, JSON
// and a PNG; what is absent is named, a plot it cannot write is one error line.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <set>
#include <string>

#include "apps/run_cli.hpp"
#include "shared_data.hpp"
#include "skip.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

TEST(EvalMirrorCurvesCli, DrawsTheSimulatedMirrorsBesideEveryRealSet) {
  const auto data = test::shared_data_dir();
  if (!std::filesystem::exists(data / "real/omni/tribots-2005")) {
    BALLSIGHT_SKIP() << "no " << data / "real/omni"
                     << " (../shared/data absent)";
  }
  const test::TempDir dir;
  const test::CliResult r = test::run_cli({"eval", "mirror-curves", "--data", data.string(),
                                           "--json", "--plot", (dir / "curves.png").string()});
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const nlohmann::json result = nlohmann::json::parse(r.stdout_text);
  std::set<std::string> names;
  for (const nlohmann::json& c : result.at("curves")) names.insert(c.at("name").get<std::string>());
  for (const char* name : {"sim unified", "sim sphere", "sim cone", "sim table", "tribots-2005",
                           "cnc-msl-nase-2016-03", "minhoteam-profile-4", "table-1"})
    EXPECT_TRUE(names.count(name)) << name;
  EXPECT_FALSE(cv::imread((dir / "curves.png").string()).empty());
}

TEST(EvalMirrorCurvesCli, WithoutTheDataTheSimulatedMirrorsAreShownAndTheMissingFilesNamed) {
  const test::TempDir dir;
  const test::CliResult r = test::run_cli({"eval", "mirror-curves", "--data", dir.path().string()});
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_NE(r.stdout_text.find("sim table"), std::string::npos) << r.stdout_text;
  EXPECT_NE(r.stderr_text.find("not found, left out: "), std::string::npos) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("tribots-2005"), std::string::npos) << r.stderr_text;
}

TEST(EvalMirrorCurvesCli, APlotItCannotWriteIsOneErrorLine) {
  const test::TempDir dir;
  const std::string plot = (dir / "no such folder" / "curves.png").string();
  test::expect_one_line_error(
      test::run_cli({"eval", "mirror-curves", "--data", dir.path().string(), "--plot", plot}),
      "no such folder");
}

}  // namespace
}  // namespace ballsight
