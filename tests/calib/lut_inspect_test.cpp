#include "ballsight/calib/lut_inspect.hpp"

#include <gtest/gtest.h>

#include <random>
#include <set>
#include <sstream>
#include <string>

#include "ballsight/camera/omni_rig.hpp"
#include "ballsight/core/error.hpp"
#include "calib/iris_ramp_table.hpp"
#include "camera/rig_tables.hpp"
#include "shared_data.hpp"
#include "skip.hpp"

namespace ballsight {
namespace {

using test::misaligned_rig_params;
using test::ramp_table;
using test::rig_table_info;
using test::true_ground_cm;

TEST(LutInspect, FindsTheNonMonotonicRegionOfTheRealIrisTables) {
  const auto tables = test::iris_px2cm_tables();
  if (tables.empty()) BALLSIGHT_SKIP() << "no iris px2cm tables in " << test::shared_data_dir();
  for (const auto& path : tables) {
    SCOPED_TRACE(path.string());
    const LutInspection in = inspect_lut(read_lut_for_inspection(path, LutFormat::automatic));
    EXPECT_EQ(in.format, "iris-px2cm");
    EXPECT_EQ(in.written_directions, 360);
    ASSERT_TRUE(in.monotonic_until_px);
    EXPECT_GE(*in.monotonic_until_px, 175.0);  // data/README.md: roughly 175-210 px
    EXPECT_LE(*in.monotonic_until_px, 210.0);
    EXPECT_GT(in.non_monotonic_directions, 0);
    // Bins below the generator's start radius hold no distances.
    ASSERT_TRUE(in.first_written_min_px && in.first_written_max_px);
    EXPECT_GE(*in.first_written_min_px, 10.0);
    EXPECT_LE(*in.first_written_max_px, 60.0);
    bool found_200 = false;
    for (const RadiusSpread& s : in.spread) {
      if (s.radius_px != 200.0) continue;
      found_200 = true;
      EXPECT_EQ(s.directions, 360);
      EXPECT_GE(s.spread_cm(), 100.0);  // directions disagree by hundreds of cm
      EXPECT_LT(s.spread_cm(), 1000.0);
    }
    EXPECT_TRUE(found_200);
  }
}

TEST(LutInspect, FirstWrittenRadiusIgnoresUninitialisedMemory) {
  const unsigned seed = 777;
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  IrisLut lut = ramp_table(500);
  std::uniform_int_distribution<int> garbage(-32768, 32767);
  for (int theta = 0; theta < IrisLut::kDirections; ++theta) {
    for (int bin = 0; bin < 500; ++bin)
      lut.at(theta, bin) = static_cast<std::int16_t>(garbage(rng));
  }
  const LutInspection in = inspect_lut(inspected_from_iris(lut, "garbage"));
  ASSERT_EQ(in.written_directions, 360);
  // A garbage value just below the first written one may look like its start: at most a bin or
  // two early.
  EXPECT_GE(*in.first_written_min_px, 49.8);
  EXPECT_EQ(*in.first_written_max_px, 50.0);
  EXPECT_EQ(*in.first_written_median_px, 50.0);

  const LutInspection zeros = inspect_lut(inspected_from_iris(ramp_table(200), "zeros"));
  EXPECT_EQ(*zeros.first_written_min_px, 20.0);
  EXPECT_EQ(*zeros.first_written_max_px, 20.0);
  EXPECT_EQ(zeros.non_monotonic_directions, 0);
  EXPECT_EQ(*zeros.monotonic_until_px, 319.9);  // the end of the written range
  EXPECT_EQ(zeros.holes, 0);
}

TEST(LutInspect, ADropOfMoreThanTheToleranceEndsTheMonotonicRange) {
  IrisLut lut = ramp_table(200);
  const int bin = 1500;  // 150 px, d = 600 cm
  const std::int16_t peak = lut.at(33, bin - 1);
  lut.at(33, bin) = static_cast<std::int16_t>(peak - 6);
  lut.at(34, bin) = static_cast<std::int16_t>(peak - 5);  // within the tolerance
  const LutInspection in = inspect_lut(inspected_from_iris(lut, "dip"));
  EXPECT_EQ(in.non_monotonic_directions, 1);
  EXPECT_EQ(*in.monotonic_until_px, 150.0);
  EXPECT_EQ(in.monotonic_until_theta_deg, 33);
  EXPECT_EQ(*in.rays[33].drop_px, 150.0);
  EXPECT_FALSE(in.rays[34].drop_px);
  EXPECT_EQ(in.holes, 0);
}

TEST(LutInspect, HolesAreImplausibleEntriesInsideTheWrittenRange) {
  IrisLut lut = ramp_table(200);
  lut.at(10, 1000) = 0;
  lut.at(10, 1001) = -4;
  lut.at(200, 2500) = 32000;  // beyond max_plausible_cm
  const LutInspection in = inspect_lut(inspected_from_iris(lut, "holes"));
  EXPECT_EQ(in.holes, 3);
  EXPECT_EQ(in.directions_with_holes, 2);
  EXPECT_EQ(in.non_monotonic_directions, 0);  // holes are skipped, not drops
  EXPECT_EQ(in.rays[10].holes, 2);
}

TEST(LutInspect, ATableOfTheTrueMappingIsMonotonicOverItsValidRange) {
  const OmniRig rig(misaligned_rig_params());
  const GroundMapInfo info = rig_table_info();
  const LutInspection in =
      inspect_lut(inspected_from_ground_map(build_ground_map(true_ground_cm(rig), info), "truth"));
  EXPECT_EQ(in.format, "ballsight");
  EXPECT_EQ(in.written_directions, 360);
  EXPECT_EQ(in.non_monotonic_directions, 0);
  EXPECT_EQ(in.holes, 0);
  EXPECT_NEAR(*in.first_written_min_px, info.min_radius_px, 0.11);
  EXPECT_NEAR(*in.first_written_max_px, info.min_radius_px, 0.11);
  EXPECT_NEAR(*in.monotonic_until_px, info.max_radius_px, 0.11);
  // The 2 deg tilt makes directions disagree, by much less than the iris tables do.
  ASSERT_FALSE(in.spread.empty());
  EXPECT_EQ(in.spread.front().radius_px, 100.0);
  EXPECT_GT(in.spread.front().spread_cm(), 5.0);
  EXPECT_LT(in.spread.front().spread_cm(), 40.0);
}

TEST(LutInspect, TextReportHasTheJsonKeysInTheSameOrder) {
  const LutInspection in = inspect_lut(inspected_from_iris(ramp_table(200), "keys"));
  std::vector<std::string> json_keys;
  const nlohmann::ordered_json json = to_json(in);
  for (auto it = json.begin(); it != json.end(); ++it) json_keys.push_back(it.key());
  std::vector<std::string> text_keys;
  std::istringstream text(format_report(in));
  for (std::string line; std::getline(text, line);) {
    if (!line.empty() && line[0] != ' ') text_keys.push_back(line.substr(0, line.find(' ')));
  }
  EXPECT_EQ(text_keys, json_keys);
}

TEST(LutInspect, UnknownFormatsAndOptionsAreRejected) {
  EXPECT_THROW(lut_format_from_string("png"), InputError);
  EXPECT_EQ(lut_format_from_string("iris-px2cm"), LutFormat::iris_px2cm);
  LutInspectOptions options;
  options.drop_tolerance_cm = -1.0;
  EXPECT_THROW(options.validate(), InputError);
}

}  // namespace
}  // namespace ballsight
