// `ballsight omni rings` end to end on a drawn ring image, the cnc-msl team's real one, and bad
// input (one line, exit status 2, the output left as it was); `eval omni-real` on the real sets.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <string>
#include <utility>

#include "apps/run_cli.hpp"
#include "ballsight/calib/sample_csv.hpp"
#include "ballsight/core/file_io.hpp"
#include "shared_data.hpp"
#include "skip.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

// Three rings around (160, 120) at 40, 70 and 95 px, as a spin over three lines leaves them.
std::string write_ring_image(const test::TempDir& dir) {
  cv::Mat1b image(240, 320, uchar{15});
  for (const int r : {40, 70, 95}) cv::circle(image, {160, 120}, r, 230, 3, cv::LINE_AA);
  const std::string path = (dir / "rings.png").string();
  cv::imwrite(path, image);
  return path;
}

TEST(OmniRingsCli, WritesOneSamplePerRingAndDirection) {
  const test::TempDir dir;
  const std::string image = write_ring_image(dir);
  const std::string out = (dir / "samples.csv").string();
  const test::CliResult r =
      test::run_cli({"omni", "rings", "--image", image, "--distances-m", "1,2,3", "--center",
                     "160,120", "--out", out, "--plot", (dir / "rings_plot.png").string()});
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_NE(r.stdout_text.find("540 samples from 180 directions x 3 rings"), std::string::npos)
      << r.stdout_text;
  EXPECT_NE(r.stdout_text.find("ring 3 at 300 cm: median radius 94.9"), std::string::npos)
      << r.stdout_text;
  EXPECT_NE(r.stdout_text.find("found in 100 % of the directions"), std::string::npos)
      << r.stdout_text;
  const std::vector<PolarSample> samples = read_polar_samples_csv(out);
  ASSERT_EQ(samples.size(), 540u);
  for (const PolarSample& s : samples) {
    const double expected = s.distance_cm == 100.0 ? 40.0 : s.distance_cm == 200.0 ? 70.0 : 95.0;
    EXPECT_NEAR(s.radius_px, expected, 0.3) << s.theta_deg << " deg, " << s.distance_cm << " cm";
  }
  EXPECT_FALSE(cv::imread((dir / "rings_plot.png").string()).empty());
  EXPECT_EQ(test::run_cli({"omni", "fit", "--samples", out, "--out", (dir / "t.bsgm").string(),
                           "--center", "160,120", "--image-size", "320x240"})
                .exit_code,
            0);
}

// `sim rings` draws a tilted rig's ring image with struts and its truth; `omni rings` at the
// centre it prints finds every ring where the truth has it unhidden, within 0.5 px (median).
TEST(OmniRingsCli, TheSimulatorsRingImageAgainstItsTruth) {
  const test::TempDir dir;
  const std::string image = (dir / "rings.png").string(), truth = (dir / "truth.csv").string();
  const test::CliResult drawn = test::run_cli(
      {"sim", "rings", "--out", image, "--truth", truth, "--distances-m", "0.5,1,1.5,2,3",
       "--line-widths-m", "0.1,0.08,0.05,0.05,0.05", "--tilt-deg", "2", "--center-offset-px",
       "3,-2", "--struts-deg", "45,165,285", "--carpet-texture", "20"});
  ASSERT_EQ(drawn.exit_code, 0) << drawn.stderr_text;
  const std::string center = "242.50,237.50";  // the image centre and the offset
  ASSERT_NE(drawn.stdout_text.find("5 rings around " + center), std::string::npos)
      << drawn.stdout_text;
  const std::string out = (dir / "samples.csv").string();
  const test::CliResult found =
      test::run_cli({"omni", "rings", "--image", image, "--distances-m", "0.5,1,1.5,2,3",
                     "--center", "242.5,237.5", "--directions", "360", "--out", out});
  ASSERT_EQ(found.exit_code, 0) << found.stderr_text;
  EXPECT_NE(found.stdout_text.find("no ring from"), std::string::npos) << found.stdout_text;
  std::map<std::pair<long, long>, double> found_at;  // (tenths of a degree, cm) -> radius
  for (const PolarSample& s : read_polar_samples_csv(out))
    found_at[{std::lround(10.0 * s.theta_deg), std::lround(s.distance_cm)}] = s.radius_px;
  std::istringstream rows(read_file(truth));
  std::string row;
  std::getline(rows, row);
  ASSERT_EQ(row, "theta_deg,distance_cm,radius_px,hidden");
  std::vector<double> errors;
  std::size_t unhidden = 0;
  for (; std::getline(rows, row);) {
    double theta = 0.0, cm = 0.0, radius = 0.0;
    int hidden = 0;
    ASSERT_EQ(std::sscanf(row.c_str(), "%lf,%lf,%lf,%d", &theta, &cm, &radius, &hidden), 4) << row;
    if (hidden) continue;
    ++unhidden;
    const auto at = found_at.find({std::lround(10.0 * theta), std::lround(cm)});
    if (at != found_at.end()) errors.push_back(std::abs(at->second - radius));
  }
  ASSERT_GT(unhidden, 1500u);
  ASSERT_GE(errors.size(), 95 * unhidden / 100);
  std::sort(errors.begin(), errors.end());
  EXPECT_LT(errors[errors.size() / 2], 0.5);
}

TEST(OmniRingsCli, BadInputIsOneLineAndLeavesTheOutput) {
  const test::TempDir dir;
  const std::string image = write_ring_image(dir);
  const std::string out = (dir / "samples.csv").string();
  write_file_atomic(out, "previous content\n");
  for (const auto& [args, problem] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"--image", image, "--distances-m", "2,1"}, "--distances-m"},
           {{"--image", image, "--distances-m", "1,2,3,4,5"}, "shows 3 rings"},
           {{"--image", image, "--distances-m", "1", "--directions", "3"}, "directions"},
           {{"--image", image, "--distances-m", "1", "--center", "900,5"}, "center"},
           {{"--image", (dir / "missing.png").string(), "--distances-m", "1"}, "missing.png"},
           {{"--image", image, "--distances-m", "1,2", "--line-toward-deg", "90"},
            "expected one distance"},
           {{"--image", image, "--distances-m", "1", "--line-toward-deg", "90", "--center",
             "160,120"},
            "does not bend like a straight line's image"},
           {{"--image", image, "--distances-m", "1", "--line-toward-deg", "nan"},
            "--line-toward-deg: expected a number"}}) {
    std::vector<std::string> command = {"omni", "rings", "--out", out};
    command.insert(command.end(), args.begin(), args.end());
    test::expect_one_line_error(test::run_cli(command), problem);
    EXPECT_EQ(read_file(out), "previous content\n");
  }
}

// MinhoTeam's frame of a straight field line 1 m ahead: one sample per direction the line is
// seen in, each at 1 m / cos(its angle off the normal), the radius growing with the distance.
TEST(OmniRingsCli, AStraightLineGivesSamplesAtItsDistanceOverTheCosine) {
  const auto dir = test::shared_data_dir() / "real/omni/minhoteam/images";
  if (!std::filesystem::exists(dir / "line_at_1.00m.png")) {
    BALLSIGHT_SKIP() << "no " << dir << " (../shared/data absent)";
  }
  const test::TempDir tmp;
  const std::string out = (tmp / "line.csv").string();
  const test::CliResult r =
      test::run_cli({"omni", "rings", "--image", (dir / "line_at_1.00m.png").string(),
                     "--distances-m", "1", "--line-toward-deg", "90", "--center", "240,240",
                     "--min-radius-px", "70", "--out", out, "--plot", (tmp / "line.png").string()});
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_NE(r.stdout_text.find("samples along a straight line at 100 cm"), std::string::npos)
      << r.stdout_text;
  std::vector<PolarSample> samples = read_polar_samples_csv(out);
  ASSERT_GT(samples.size(), 100u);
  std::sort(samples.begin(), samples.end(), [](const PolarSample& a, const PolarSample& b) {
    return a.distance_cm < b.distance_cm;
  });
  EXPECT_NEAR(samples.front().distance_cm, 100.0, 0.1);
  EXPECT_GT(samples.back().distance_cm, 250.0);  // over 66 deg off the normal
  EXPECT_GT(samples.back().radius_px, samples.front().radius_px + 40.0);
  EXPECT_EQ(cv::imread((tmp / "line.png").string()).size(), cv::Size(960, 960));  // drawn at 2x
}

// On the real sets with several directions, ballsight's held-out median is below the paper's
// polynomial's on both splits (paper-mlp takes minutes a fit: docs/RESULTS.md has it), and the
// report carries the data's floor.
TEST(EvalOmniRealCli, BallsightBeatsThePolynomialOnTheRealSets) {
  const auto data = test::shared_data_dir();
  if (!std::filesystem::exists(data / "real/omni/tribots-2005")) {
    BALLSIGHT_SKIP() << "no " << data / "real/omni"
                     << " (../shared/data absent)";
  }
  const test::CliResult r = test::run_cli(
      {"eval", "omni-real", "--data", data.string(), "--methods", "poly,ballsight", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const nlohmann::json result = nlohmann::json::parse(r.stdout_text);
  int compared = 0;
  for (const nlohmann::json& set : result.at("sets")) {
    const std::string name = set.at("name");
    if (name != "tribots-2005" && name != "cnc-msl-nase-2016-03") continue;
    std::map<std::string, double> poly, ours;
    for (const nlohmann::json& s : set.at("scores")) {
      (s.at("method") == "poly" ? poly : ours)[s.at("split")] = s.at("median_cm");
    }
    for (const char* split : {"directions", "distance"}) {
      EXPECT_LT(ours.at(split), 0.7 * poly.at(split)) << name << " " << split;
      ++compared;
    }
    // The data's own floor on the same folds (neighbouring directions read along their rays): on
    // these ring sets a direction is predicted from its neighbours to about a centimetre, below
    // the polynomial; without paper-mlp no target is judged.
    std::map<std::string, double> floor;
    for (const nlohmann::json& f : set.at("floor")) floor[f.at("split")] = f.at("median_cm");
    ASSERT_EQ(floor.size(), 2u) << name;
    EXPECT_GT(floor.at("directions"), 0.5) << name;
    EXPECT_LT(floor.at("directions"), 0.7 * poly.at("directions")) << name;
    EXPECT_TRUE(set.at("targets").empty()) << name;
  }
  EXPECT_EQ(compared, 4);
}

// A set no method can fit is one error line, not a crash of the worker threads.
TEST(EvalOmniRealCli, ASetTooSmallToFitIsAnError) {
  const test::TempDir dir;
  std::filesystem::create_directories(dir / "real/omni/tribots-2005");
  write_file_atomic(dir / "real/omni/tribots-2005/samples_0.5-4m.csv",
                    "theta_deg,radius_px,distance_cm\n0,10,50\n10,10,50\n");
  test::expect_one_line_error(test::run_cli({"eval", "omni-real", "--data", dir.path().string(),
                                             "--methods", "poly,ballsight", "--jobs", "2"}),
                              "samples");
}

}  // namespace
}  // namespace ballsight
