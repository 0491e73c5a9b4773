// `ballsight omni markers` end to end: a rendered calibration frame becomes samples whose pixels
// are the markers' true projections, ready for omni fit; bad input is one line, exit status 2.

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "apps/run_cli.hpp"
#include "ballsight/calib/sample_csv.hpp"
#include "ballsight/core/angle.hpp"
#include "ballsight/core/conventions.hpp"
#include "ballsight/core/file_io.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

TEST(OmniMarkersCli, FindsEveryMarkerOfARenderedFrameAtItsTruePixel) {
  const test::TempDir dir;
  ASSERT_EQ(test::run_cli({"sim", "omni", "--out", dir.path().string(), "--frames", "1", "--seed",
                           "3", "--noise", "3"})
                .exit_code,
            0);
  const std::string samples = (dir / "samples.csv").string();
  const test::CliResult r = test::run_cli(
      {"omni", "markers", "--image", (dir / "omni_0000.png").string(), "--out", samples});
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_NE(r.stdout_text.find("matched 324 of 324 layout markers"), std::string::npos)
      << r.stdout_text;

  // Truth: each marker's projected centre, by (distance, bearing) rounded to cm and degrees.
  const nlohmann::json truth = nlohmann::json::parse(read_file(dir / "omni_0000.json"));
  std::map<std::pair<long, long>, Vec2> pixel_of;
  for (const nlohmann::json& m : truth.at("markers")) {
    const auto& p = m.at("pixel");
    pixel_of[{std::lround(100.0 * m.at("distance_m").get<double>()),
              std::lround(wrap_deg_360(m.at("bearing_deg").get<double>()))}] = {p[0].get<double>(),
                                                                                p[1].get<double>()};
  }
  const std::vector<PolarSample> found = read_polar_samples_csv(samples);
  ASSERT_EQ(found.size(), 324u);
  const Vec2 center(319.5, 239.5);
  for (const PolarSample& s : found) {
    ASSERT_TRUE(s.bearing_deg);
    // The samples' bearing is in the paper's image-angle convention (docs/conventions.md).
    const double robot_bearing_deg =
        wrap_deg_360(robot_bearing_deg_from_image_theta_deg(*s.bearing_deg));
    const auto key = std::make_pair(std::lround(s.distance_cm), std::lround(robot_bearing_deg));
    ASSERT_TRUE(pixel_of.contains(key)) << s.distance_cm << " cm, " << *s.bearing_deg << " deg";
    const Vec2 pixel = pixel_from_image_polar({s.theta_deg, s.radius_px}, center);
    EXPECT_LT((pixel - pixel_of.at(key)).norm(), 0.6)
        << s.distance_cm << " cm, " << *s.bearing_deg << " deg";
  }
  EXPECT_EQ(test::run_cli({"omni", "fit", "--samples", samples, "--out", (dir / "t.bsgm").string(),
                           "--center", "319.5,239.5", "--image-size", "640x480"})
                .exit_code,
            0);
}

TEST(OmniMarkersCli, BadInputIsOneLineAndLeavesTheOutput) {
  const test::TempDir dir;
  ASSERT_EQ(test::run_cli({"sim", "omni", "--out", dir.path().string(), "--frames", "2"}).exit_code,
            0);
  const std::string out = (dir / "samples.csv").string();
  write_file_atomic(out, "previous content\n");
  const std::string calibration = (dir / "omni_0000.png").string();
  for (const auto& [args, problem] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"--image", (dir / "omni_0001.png").string()}, "matched 0 of 324 layout markers"},
           {{"--image", calibration, "--marker-bgr", "0,300,0"}, "--marker-bgr"},
           {{"--image", calibration, "--center", "x"}, "--center"},
           {{"--image", calibration, "--min-cm", "10"}, "min_distance_m"},
           {{"--image", calibration, "--marker-diameter-cm", "-3"}, "--marker-diameter-cm"},
           {{"--image", (dir / "missing.png").string()}, "missing.png"}}) {
    std::vector<std::string> command = {"omni", "markers", "--out", out};
    command.insert(command.end(), args.begin(), args.end());
    const test::CliResult r = test::run_cli(command);
    EXPECT_EQ(r.exit_code, 2) << r.stderr_text;
    EXPECT_EQ(test::line_count(r.stderr_text), 1) << r.stderr_text;
    EXPECT_NE(r.stderr_text.find(problem), std::string::npos) << r.stderr_text;
    EXPECT_EQ(read_file(out), "previous content\n");
  }
}

}  // namespace
}  // namespace ballsight
