// `ballsight eval omni` end to end on the fast methods: the JSON shape and ballsight's
// targets on the simulated paper experiment; bad options end with one line and exit status 2.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "apps/run_cli.hpp"

namespace ballsight {
namespace {

TEST(EvalOmniCli, BallsightMeetsThePapersPrecisionTargets) {
  const test::CliResult r = test::run_cli(
      {"eval", "omni", "--methods", "ballsight,ballsight-auto,oracle", "--seed", "1", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const nlohmann::json methods = nlohmann::json::parse(r.stdout_text).at("methods");
  ASSERT_EQ(methods.size(), 3u);
  for (const std::string method : {"ballsight", "ballsight-auto", "oracle"}) {
    const nlohmann::json& by_distance = methods.at(method).at("by_distance");
    for (const std::string distance : {"120", "200", "285"}) {
      SCOPED_TRACE(method + " at " + distance + " cm");
      const nlohmann::json& d = by_distance.at(distance);
      EXPECT_EQ(d.at("found").get<int>(), 12);
      for (const char* key : {"mean_error_cm", "std_x_cm", "std_y_cm"}) {
        EXPECT_GE(d.at(key).get<double>(), 0.0);
      }
    }
  }
  const nlohmann::json& ballsight = methods.at("ballsight").at("by_distance");
  EXPECT_LE(ballsight.at("120").at("mean_error_cm").get<double>(), 2.0);
  EXPECT_LE(ballsight.at("285").at("mean_error_cm").get<double>(), 5.0);
  for (const char* axis : {"std_x_cm", "std_y_cm"}) {
    EXPECT_LE(ballsight.at("120").at(axis).get<double>(), 1.0);
    EXPECT_LE(ballsight.at("285").at(axis).get<double>(), 2.5);
  }
  // Calibrated without clicking, from the markers it finds, ballsight is within 1.3x the oracle.
  for (const std::string distance : {"120", "200", "285"}) {
    const auto mean_error = [&](const std::string& method) {
      return methods.at(method).at("by_distance").at(distance).at("mean_error_cm").get<double>();
    };
    EXPECT_LE(mean_error("ballsight-auto"), 1.3 * mean_error("oracle")) << distance << " cm";
  }
}

TEST(EvalOmniCli, BadOptionsAreOneLine) {
  for (const auto& [args, problem] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"eval", "omni", "--methods", "ballsight,cubic"}, "unknown method 'cubic'"},
           {{"eval", "omni", "--measured-height-sigma-cm", "-1"}, "measured_height_sigma_cm"},
           {{"eval", "omni", "--click-noise-px", "20"}, "click_noise_px"}}) {
    const test::CliResult r = test::run_cli(args);
    EXPECT_EQ(r.exit_code, 2) << r.stderr_text;
    EXPECT_EQ(test::line_count(r.stderr_text), 1) << r.stderr_text;
    EXPECT_NE(r.stderr_text.find(problem), std::string::npos) << r.stderr_text;
  }
}

}  // namespace
}  // namespace ballsight
