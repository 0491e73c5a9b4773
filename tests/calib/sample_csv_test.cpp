#include "ballsight/calib/sample_csv.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>

#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "calib/calib_fixtures.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

using test::input_error;

std::string parse_error(const std::string& text) {
  return input_error([&] { parse_polar_samples_csv(text, "s.csv"); });
}

TEST(SampleCsv, RoundTripIsExact) {
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> angle(0.0, 360.0), radius(1e-3, 500.0),
        distance(1.0, 900.0);
    std::vector<PolarSample> samples;
    for (int i = 0; i < 50; ++i) {
      PolarSample s{angle(rng), radius(rng), distance(rng), std::nullopt};
      if (seed != 1 && i % 3 != 0) s.bearing_deg = angle(rng);  // some rows without bearing
      samples.push_back(s);
    }
    const std::vector<PolarSample> back =
        parse_polar_samples_csv(format_polar_samples_csv(samples), "round trip");
    ASSERT_EQ(back.size(), samples.size());
    for (std::size_t i = 0; i < samples.size(); ++i) {
      EXPECT_EQ(back[i].theta_deg, samples[i].theta_deg);
      EXPECT_EQ(back[i].radius_px, samples[i].radius_px);
      EXPECT_EQ(back[i].distance_cm, samples[i].distance_cm);
      EXPECT_EQ(back[i].bearing_deg, samples[i].bearing_deg);
    }
  }
}

TEST(SampleCsv, FileRoundTrip) {
  const test::TempDir dir;
  const std::vector<PolarSample> samples = {{0.0, 81.0, 60.0, {}}, {10.0, 104.738, 110.0, {}}};
  write_polar_samples_csv(dir / "s.csv", samples);
  EXPECT_EQ(read_file(dir / "s.csv"), "theta_deg,radius_px,distance_cm\n0,81,60\n10,104.738,110\n");
  EXPECT_EQ(read_polar_samples_csv(dir / "s.csv").size(), 2u);
}

TEST(SampleCsv, AcceptsAnyColumnOrderCrlfBomAndBlankLines) {
  const std::string text =
      "\xEF\xBB\xBF"
      "distance_cm, bearing_deg ,theta_deg,radius_px\r\n"
      "\r\n"
      "60,91.5,90,81\r\n"
      "110,,0, 105 \r\n";
  const std::vector<PolarSample> samples = parse_polar_samples_csv(text, "s.csv");
  ASSERT_EQ(samples.size(), 2u);
  EXPECT_EQ(samples[0].theta_deg, 90.0);
  EXPECT_EQ(samples[0].radius_px, 81.0);
  EXPECT_EQ(samples[0].distance_cm, 60.0);
  EXPECT_EQ(samples[0].bearing_deg, 91.5);
  EXPECT_EQ(samples[1].radius_px, 105.0);
  EXPECT_FALSE(samples[1].bearing_deg);
}

// Every kind of bad row names file:line:column and what was expected.
TEST(SampleCsv, BadRowsNameFileLineAndColumn) {
  const std::string header = "theta_deg,radius_px,distance_cm\n";
  const std::string good = "0,81,60\n";
  struct Case {
    std::string text;
    std::string location;
    std::string expected;
  };
  const Case cases[] = {
      {header + good + "10,nan,60\n", "s.csv:3:4:", "radius_px: expected a finite number"},
      {header + "10,81,inf\n", "s.csv:2:7:", "distance_cm: expected a finite number"},
      {header + "10,8x1,60\n", "s.csv:2:4:", "got '8x1'"},
      {header + "10,,60\n", "s.csv:2:4:", "radius_px: expected a finite number"},
      {header + "360,81,60\n", "s.csv:2:1:", "theta_deg: expected an angle in [0, 360) deg"},
      {header + "-1,81,60\n", "s.csv:2:1:", "theta_deg: expected an angle"},
      {header + "10,-81,60\n", "s.csv:2:4:", "radius_px: expected a radius in (0, 100000) px"},
      {header + "10,81,0\n", "s.csv:2:7:", "distance_cm: expected a distance"},
      {header + good + good + "10,81\n", "s.csv:4:6:", "missing column distance_cm"},
      {header + "10,81,60,5\n", "s.csv:2:10:", "extra column 4"},
      {"theta_deg,radius_px,distance_cm,bearing_deg\n10,81,60,400\n",
       "s.csv:2:10:", "bearing_deg: expected an angle"},
      {"theta_deg,radius_px\n10,81\n", "s.csv:1:1:", "header lacks column distance_cm"},
      {"theta_deg,radius_px,distance_cm,colour\n", "s.csv:1:33:", "unknown column 'colour'"},
      {"theta_deg,radius_px,theta_deg,distance_cm\n", "s.csv:1:21:", "duplicate column"},
      {"", "s.csv:1:1:", "empty file"},
      {header, "s.csv:2:1:", "no sample rows"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.text);
    const std::string message = parse_error(c.text);
    EXPECT_EQ(message.rfind(c.location, 0), 0u) << message;
    EXPECT_NE(message.find(c.expected), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(SampleCsv, UnreadableFileNamesThePath) {
  const std::string message =
      input_error([] { read_polar_samples_csv("/nonexistent/samples.csv"); });
  EXPECT_NE(message.find("/nonexistent/samples.csv"), std::string::npos) << message;
}

}  // namespace
}  // namespace ballsight
