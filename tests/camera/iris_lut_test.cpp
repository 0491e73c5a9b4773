#include "ballsight/camera/iris_lut.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "ballsight/core/conventions.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "camera/rig_tables.hpp"
#include "shared_data.hpp"
#include "skip.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

namespace fs = std::filesystem;
using test::iris_px2cm_tables;
using test::misaligned_rig_params;
using test::rig_table_info;
using test::true_ground_cm;

std::string read_error(const fs::path& path, IrisLutKind kind) {
  try {
    read_iris_lut(path, kind);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// The distance along rays of `rig`'s true mapping around `center`.
RadialDistanceCm true_radial_cm(const OmniRig& rig, const Vec2& center) {
  return [&rig, center](double theta_deg, double radius_px) -> std::optional<double> {
    const std::optional<Vec2> p_cm =
        true_ground_cm(rig)(pixel_from_image_polar({theta_deg, radius_px}, center));
    if (!p_cm) return std::nullopt;
    return p_cm->norm();
  };
}

TEST(IrisLut, ReadsRealTablesAsRawLittleEndianInt16) {
  const auto tables = iris_px2cm_tables();
  if (tables.empty()) BALLSIGHT_SKIP() << "no iris px2cm tables in " << test::shared_data_dir();
  for (const fs::path& path : tables) {
    SCOPED_TRACE(path.string());
    const IrisLut lut = read_iris_lut(path, IrisLutKind::px2cm);
    const std::string raw = read_file(path);
    const auto raw_entry = [&](std::size_t i) {
      return static_cast<std::int16_t>(static_cast<unsigned char>(raw[2 * i]) |
                                       (static_cast<unsigned char>(raw[2 * i + 1]) << 8));
    };
    for (const auto& [theta, bin] :
         std::initializer_list<std::pair<int, int>>{{0, 0}, {0, 600}, {90, 1500}, {359, 3199}}) {
      EXPECT_EQ(lut.at(theta, bin), raw_entry(static_cast<std::size_t>(theta) * 3200 + bin));
    }
    // The robots' read: (int)angle * 3200 + (int)(dist * 10).
    EXPECT_EQ(iris_distance_cm(lut, 90.7, 150.06), lut.at(90, 1500));
    // Writing gives the same bytes back.
    const test::TempDir dir;
    const fs::path copy = dir / "copy.bin";
    write_iris_lut(copy, lut);
    EXPECT_EQ(read_file(copy), raw);
  }
}

TEST(IrisLut, WrongSizesAreRejectedNamingTheFile) {
  const test::TempDir dir;
  const fs::path path = dir / "bad.bin";
  write_file_atomic(path, "");
  EXPECT_NE(read_error(path, IrisLutKind::px2cm).find(path.string() + ": empty file"),
            std::string::npos);
  write_file_atomic(path, std::string(864000, '\1'));  // a cm2px table read as px2cm
  EXPECT_NE(read_error(path, IrisLutKind::px2cm)
                .find("truncated: expected 2304000 bytes, got 864000 (an iris px2cm table is "
                      "360 x 3200 int16)"),
            std::string::npos)
      << read_error(path, IrisLutKind::px2cm);
  EXPECT_EQ(read_error(path, IrisLutKind::cm2px), "");
  write_file_atomic(path, std::string(864001, '\1'));
  EXPECT_NE(read_error(path, IrisLutKind::cm2px).find("expected 864000 bytes, got 864001"),
            std::string::npos);
  fs::remove(path);
  EXPECT_NE(read_error(path, IrisLutKind::px2cm).find(path.string()), std::string::npos);
  EXPECT_THROW(IrisLut(IrisLutKind::px2cm, std::vector<std::int16_t>(100)), InputError);
}

TEST(IrisLut, IndexesExactlyAsTheRobots) {
  IrisLut px2cm(IrisLutKind::px2cm);
  px2cm.at(12, 345) = 99;
  px2cm.at(359, 3199) = 7;
  EXPECT_EQ(iris_distance_cm(px2cm, 12.99, 34.59), 99);
  EXPECT_EQ(iris_distance_cm(px2cm, 12.0, 34.5), 99);
  EXPECT_EQ(iris_distance_cm(px2cm, 13.0, 34.5), 0);
  EXPECT_EQ(iris_distance_cm(px2cm, 12.5, 34.49), 0);
  EXPECT_EQ(iris_distance_cm(px2cm, 359.999, 319.99), 7);
  EXPECT_FALSE(iris_distance_cm(px2cm, 360.0, 10.0));
  EXPECT_FALSE(iris_distance_cm(px2cm, -0.01, 10.0));
  EXPECT_FALSE(iris_distance_cm(px2cm, 10.0, 320.0));
  EXPECT_FALSE(iris_distance_cm(px2cm, std::nan(""), 10.0));

  IrisLut cm2px(IrisLutKind::cm2px);
  cm2px.at(90, 250) = 1234;
  EXPECT_EQ(iris_radius_px(cm2px, 90.3, 250.7), 123.4);
  EXPECT_FALSE(iris_radius_px(cm2px, 90.3, 1200.0));
}

TEST(IrisLut, RobotPointUsesTheImageAngleMinus90AsBearing) {
  IrisLut px2cm(IrisLutKind::px2cm);
  for (int theta = 0; theta < 360; ++theta) {
    for (int bin = 400; bin < 600; ++bin) px2cm.at(theta, bin) = 100;
  }
  const Vec2 center(320.0, 240.0);
  const auto up = iris_robot_point_cm(px2cm, center + Vec2(0.0, -50.0), center);
  ASSERT_TRUE(up);  // image up = robot forward
  EXPECT_NEAR(up->x(), 100.0, 1e-9);
  EXPECT_NEAR(up->y(), 0.0, 1e-9);
  const auto right = iris_robot_point_cm(px2cm, center + Vec2(50.0, 0.0), center);
  ASSERT_TRUE(right);  // image right = robot right (-y)
  EXPECT_NEAR(right->x(), 0.0, 1e-9);
  EXPECT_NEAR(right->y(), -100.0, 1e-9);
  EXPECT_FALSE(iris_robot_point_cm(px2cm, center + Vec2(30.0, 0.0), center));  // unwritten
}

TEST(IrisLut, BuiltFromTheTrueMappingReproducesDistancesWithinQuantisation) {
  const OmniRig rig;  // aligned: distance depends on the radius only
  const IrisLut lut = build_iris_px2cm(true_radial_cm(rig, rig.principal_point()));
  EXPECT_EQ(lut.at(0, 0), 0);  // the centre of the image sees the robot itself: distance 0
  const unsigned seed = 4242;
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> theta(0.0, 360.0), radius(30.0, 190.0);
  double worst_cm = 0.0;
  for (int i = 0; i < 5000; ++i) {
    const Vec2 pixel = pixel_from_image_polar({theta(rng), radius(rng)}, rig.principal_point());
    const auto table = iris_robot_point_cm(lut, pixel, rig.principal_point());
    const auto truth = true_ground_cm(rig)(pixel);
    ASSERT_TRUE(table && truth);
    worst_cm = std::max(worst_cm, (*table - *truth).norm());
  }
  // Half a 0.1 px bin at <= 8 cm/px plus rounding to whole cm.
  EXPECT_LT(worst_cm, 0.5 + 0.05 * 8.0);
}

TEST(IrisLut, GroundMapFromIrisConvertsEveryPixelAsTheRobots) {
  const OmniRig rig(misaligned_rig_params());
  const GroundMapInfo info = rig_table_info();
  const IrisLut lut = build_iris_px2cm(true_radial_cm(rig, info.image_center_px));
  const GroundMap map = ground_map_from_iris_px2cm(lut, info);
  int checked = 0;
  for (int y = 0; y < info.height; y += 3) {
    for (int x = 0; x < info.width; x += 3) {
      if (!map.in_valid_range(Vec2(x, y))) continue;
      const auto robot = iris_robot_point_cm(lut, Vec2(x, y), info.image_center_px);
      const GroundCell cell = map.at(x, y);
      ASSERT_TRUE(robot && cell.valid());
      EXPECT_EQ(cell.x_cm, static_cast<float>(robot->x()));
      EXPECT_EQ(cell.y_cm, static_cast<float>(robot->y()));
      ++checked;
    }
  }
  EXPECT_GT(checked, 10000);
}

// iris -> GroundMap -> iris, bins inside the valid range. The GroundMap holds the robots'
// floor()-read values at whole pixels; reading back at bin centres interpolates between pixels
// whose values come from neighbouring bins, so the round trip is exact only up to one bin's
// change and rounding.
TEST(IrisLut, RoundTripThroughAGroundMap) {
  const OmniRig rig(misaligned_rig_params());
  const GroundMapInfo info = rig_table_info();
  const IrisLut lut = build_iris_px2cm(true_radial_cm(rig, info.image_center_px));
  const IrisLut back = iris_px2cm_from_ground_map(ground_map_from_iris_px2cm(lut, info));
  int checked = 0;
  for (int theta = 0; theta < 360; ++theta) {
    for (int bin = 320; bin < 1980; ++bin) {
      // The change to the neighbouring bins, along the ray and across directions.
      int step_cm = 0;
      for (const auto& [dt, db] :
           std::initializer_list<std::pair<int, int>>{{0, -1}, {0, 1}, {359, 0}, {1, 0}}) {
        step_cm =
            std::max(step_cm, std::abs(lut.at((theta + dt) % 360, bin + db) - lut.at(theta, bin)));
      }
      const int error_cm = std::abs(back.at(theta, bin) - lut.at(theta, bin));
      ASSERT_LE(error_cm, 1 + step_cm) << theta << " deg, bin " << bin;
      ++checked;
    }
    EXPECT_EQ(back.at(theta, 250), 0);  // outside the valid range: unwritten, as the robots'
  }
  EXPECT_EQ(checked, 360 * 1660);
}

}  // namespace
}  // namespace ballsight
