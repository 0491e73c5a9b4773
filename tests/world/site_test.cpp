#include "ballsight/world/site.hpp"

#include <gtest/gtest.h>

#include <string>

#include "ballsight/core/error.hpp"
#include "example_site.hpp"

namespace ballsight {
namespace {

const std::filesystem::path& kExample = test::kExampleSite;

TEST(Site, TheDocumentedExampleReads) {
  const Site site = read_site(kExample);
  EXPECT_EQ(site.file, kExample);
  EXPECT_DOUBLE_EQ(site.court.length_m, 23.77);
  EXPECT_DOUBLE_EQ(site.court.area_width_m, 18.0);
  EXPECT_DOUBLE_EQ(site.ball_radius_m, 0.0335);
  ASSERT_EQ(site.reference_balls.size(), 12u);
  EXPECT_EQ(site.reference_balls[0].name, "singles_ne");  // file order
  EXPECT_EQ(site.reference_balls[11].name, "net_south");
  EXPECT_EQ(site.reference_balls[11].floor_position_m, Vec2(0.0, -5.46));
  EXPECT_EQ(site.reference_center_in_field(site.reference_balls[0]), Vec3(11.86, 4.09, 0.02));
  EXPECT_EQ(site.colours.reference_ball.bgr(), cv::Vec3b(20, 100, 255));
  EXPECT_DOUBLE_EQ(site.robot.collector_width_m, 0.70);
  ASSERT_EQ(site.cameras.size(), 4u);
  const SiteCamera& c = site.cameras[2];
  EXPECT_EQ(c.name, "sw");
  EXPECT_EQ(c.source.kind, CameraSource::Kind::file);
  EXPECT_EQ(c.source.path, kExample.parent_path() / "court_0000_cam2.png");
  EXPECT_EQ(c.calibration_file, kExample.parent_path() / "cam2.yml");
  ASSERT_TRUE(c.position_hint_m.has_value());
  EXPECT_EQ(*c.position_hint_m, Vec3(-18.25, -9.25, 5.0));
}

constexpr const char* kMinimal = R"(reference_balls:
  positions_m:
    a: [1, 2]
    b: [3, 4]
    c: [5, 6]
    d: [7, 8.5]
cameras:
  - name: one
    source: {folder: images/one}
    calibration: one.yml
  - name: two
    source: {device: 2}
    calibration: calib/two.yml
  - name: three
    source:
      url: rtsp://10.0.0.3/stream
    calibration: three.yml
)";

TEST(Site, DefaultsAndEverySourceKind) {
  const Site site = parse_site(kMinimal, "/data/site.yml");
  EXPECT_DOUBLE_EQ(site.reference_ball_radius_m, 0.02);
  EXPECT_DOUBLE_EQ(site.court.width_m, 10.97);
  EXPECT_EQ(site.colours.ball.bgr(), SiteColours{}.ball.bgr());
  ASSERT_EQ(site.cameras.size(), 3u);
  EXPECT_EQ(site.cameras[0].source.kind, CameraSource::Kind::folder);
  EXPECT_EQ(site.cameras[0].source.path, std::filesystem::path("/data/images/one"));
  EXPECT_EQ(site.cameras[1].source.kind, CameraSource::Kind::device);
  EXPECT_EQ(site.cameras[1].source.device, 2);
  EXPECT_EQ(site.cameras[1].calibration_file, std::filesystem::path("/data/calib/two.yml"));
  EXPECT_EQ(site.cameras[2].source.kind, CameraSource::Kind::url);
  EXPECT_EQ(site.cameras[2].source.url, "rtsp://10.0.0.3/stream");
  EXPECT_FALSE(site.cameras[2].position_hint_m.has_value());
  EXPECT_EQ(camera_source_kind_name(CameraSource::Kind::url), "url");
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

// The message must be exactly this (file, line, key, what was expected).
void expect_error(const std::string& text, const std::string& expected) {
  try {
    parse_site(text, "site.yml");
    ADD_FAILURE() << "no error, expected: " << expected;
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), expected);
  }
}

TEST(Site, WrongTypesNameTheKeyAndLine) {
  const std::string base = std::string(kMinimal) + "colours:\n  ball: [225, 250, 45]\n";
  expect_error(replaced(base, "ball: [225, 250, 45]", "ball: [225, 250]"),
               "site.yml:19: key 'colours.ball' expected a list of 3 integers in [0, 255]");
  expect_error(replaced(base, "ball: [225, 250, 45]", "ball: yellow"),
               "site.yml:19: key 'colours.ball' expected a list of 3 integers in [0, 255]");
  expect_error(replaced(base, "ball: [225, 250, 45]", "ball: [225, 250, 300]"),
               "site.yml:19: key 'colours.ball' expected a list of 3 integers in [0, 255]");
  expect_error(replaced(kMinimal, "d: [7, 8.5]", "d: [7, eight]"),
               "site.yml:6: key 'reference_balls.positions_m.d' expected a list of 2 numbers");
  expect_error(replaced(kMinimal, "{device: 2}", "{device: two}"),
               "site.yml:12: key 'cameras[1].source.device' expected an integer");
  expect_error(replaced(kMinimal, "cameras:\n", "ball_radius_m: -1\ncameras:\n"),
               "site.yml:7: key 'ball_radius_m' must be positive, got -1");
  expect_error(std::string(kMinimal) + "court: 3\n",
               "site.yml:18: key 'court' expected a map of keys");
  expect_error(replaced(kMinimal, "url: rtsp://", "url: ftp://"),
               "site.yml:16: key 'cameras[2].source.url' expected an rtsp://, http:// or https:// "
               "address");
}

TEST(Site, UnknownKeysNameTheKeyAndLine) {
  expect_error(std::string(kMinimal) + "colours:\n  bal: [1, 2, 3]\n",
               "site.yml:19: unknown key 'colours.bal' (expected one of: ball, reference_ball, "
               "robot_front, robot_back)");
  expect_error(replaced(kMinimal, "    calibration: one.yml\n",
                        "    calibration: one.yml\n    calibraton: one.yml\n"),
               "site.yml:11: unknown key 'cameras[0].calibraton' (expected one of: name, source, "
               "calibration, position_hint_m)");
  expect_error("cameraz: []\n" + std::string(kMinimal),
               "site.yml:1: unknown key 'cameraz' (expected one of: court, ball_radius_m, "
               "reference_balls, colours, robot, cameras)");
}

TEST(Site, MissingAndRepeatedKeys) {
  expect_error(replaced(kMinimal, "    calibration: one.yml\n", ""),
               "site.yml:8: key 'cameras[0].calibration' missing");
  expect_error(replaced(kMinimal, "    d: [7, 8.5]\n", "    c: [7, 8.5]\n"),
               "site.yml:6: key 'reference_balls.positions_m.c' appears twice");
  expect_error(replaced(kMinimal, "    d: [7, 8.5]\n", ""),
               "site.yml:3: key 'reference_balls.positions_m' needs at least 4 reference balls, "
               "got 3");
  expect_error(replaced(kMinimal, "{device: 2}", "{device: 2, file: a.png}"),
               "site.yml:12: key 'cameras[1].source' expected exactly one of file, folder, "
               "device, url");
  expect_error(replaced(kMinimal, "name: two", "name: one"),
               "site.yml:11: key 'cameras[1]' repeats camera name 'one'");
  expect_error(replaced(kMinimal, "calib/two.yml", "one.yml"),
               "site.yml:11: key 'cameras[1]' repeats calibration file one.yml");
  expect_error(
      "cameras: []\nreference_balls: {positions_m: {a: [1, 2], b: [1, 3], c: [2, 2], "
      "d: [3, 3]}}\n",
      "site.yml:1: key 'cameras' needs at least one camera");
}

TEST(Site, CorruptYamlAndMissingFile) {
  try {
    parse_site("reference_balls: [1, 2\ncameras: {\n", "site.yml");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("site.yml:", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("not valid YAML"), std::string::npos) << e.what();
  }
  expect_error("- a\n- b\n", "site.yml:1: expected a YAML map of keys at the top of the file");
  try {
    read_site("/nonexistent/site.yml");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/site.yml"), std::string::npos) << e.what();
  }
}

TEST(Site, TheNetAndTheRobotsLimits) {
  const Site defaults = parse_site(kMinimal, "site.yml");
  EXPECT_TRUE(defaults.court.net);
  EXPECT_DOUBLE_EQ(defaults.court.net_posts_outside_m, 0.914);
  EXPECT_DOUBLE_EQ(defaults.robot.max_speed_mps, 1.0);
  EXPECT_DOUBLE_EQ(defaults.robot.collector_x_m, 0.30);
  const Site site = parse_site(std::string(kMinimal) +
                                   "court:\n  net: false\nrobot:\n  max_speed_mps: 0.6\n"
                                   "  turn_rate_dps: 45\n  collector_x_m: 0.25\n",
                               "site.yml");
  EXPECT_FALSE(site.court.net);
  EXPECT_DOUBLE_EQ(site.robot.max_speed_mps, 0.6);
  EXPECT_DOUBLE_EQ(site.robot.turn_rate_dps, 45.0);
  EXPECT_DOUBLE_EQ(site.robot.collector_x_m, 0.25);
  expect_error(std::string(kMinimal) + "court:\n  net: maybe\n",
               "site.yml:19: key 'court.net' expected true or false");
  // A fence too narrow to drive round the posts (10.97 / 2 + 0.914 + 0.5 m from the centre).
  expect_error(std::string(kMinimal) + "court:\n  area_width_m: 13\n",
               "site.yml:19: key 'court' area_width_m must leave room to drive round the net "
               "posts (more than 13.80 m)");
  // A fence lane as wide as half the fenced area leaves no room inside it.
  expect_error(std::string(kMinimal) + "court:\n  fence_lane_m: 9\n",
               "site.yml:19: key 'court' fence_lane_m must leave room inside the fence (less "
               "than half of area_width_m)");
}

TEST(Site, TheBasketAndWhereItIsEmptied) {
  const Site defaults = parse_site(kMinimal, "site.yml");
  EXPECT_EQ(defaults.robot.capacity, 60);
  EXPECT_DOUBLE_EQ(defaults.robot.unload_s, 5.0);
  EXPECT_EQ(defaults.unload_point(), Vec2(16.5, 0.0));  // 1.5 m inside the 36 m area's east end
  const Site site = parse_site(std::string(kMinimal) +
                                   "robot:\n  capacity: 25\n  unload_m: [-15, 2]\n"
                                   "  unload_s: 8\n",
                               "site.yml");
  EXPECT_EQ(site.robot.capacity, 25);
  EXPECT_EQ(site.unload_point(), Vec2(-15.0, 2.0));
  EXPECT_DOUBLE_EQ(site.robot.unload_s, 8.0);
  expect_error(std::string(kMinimal) + "robot:\n  capacity: 0\n",
               "site.yml:19: key 'robot.capacity' must be 1 to 1000 balls, got 0");
  expect_error(std::string(kMinimal) + "robot:\n  unload_m: [17.8, 0]\n",
               "site.yml:19: key 'robot.unload_m' must be clear of the fence's lane and of the "
               "net's (unload_m 17.80, 0.00)");
  expect_error(std::string(kMinimal) + "robot:\n  unload_m: [0.1, 3]\n",
               "site.yml:19: key 'robot.unload_m' must be clear of the fence's lane and of the "
               "net's (unload_m 0.10, 3.00)");
  // A fence lane wider than the default's 1.5 m: the default point is refused, a given one is not.
  expect_error(std::string(kMinimal) + "court:\n  fence_lane_m: 2\n",
               "site.yml: the default unload point (16.50, 0.00) is not clear of the fence's lane: "
               "give robot.unload_m");
  EXPECT_EQ(parse_site(std::string(kMinimal) + "court:\n  fence_lane_m: 2\nrobot:\n  unload_m: "
                                               "[15, 0]\n",
                       "site.yml")
                .unload_point(),
            Vec2(15.0, 0.0));
}

}  // namespace
}  // namespace ballsight

namespace ballsight {
namespace {

// A site written as text reads back to the same values, every digit kept: what a recording keeps
// to replay its run.
TEST(SiteText, ReadsBackToTheSameSite) {
  Site site = read_site(kExample);
  site.court.fence_lane_m = 0.1 + 0.2;  // 0.30000000000000004: needs every digit
  site.ball_radius_m = 1.0 / 30.0;
  site.robot.unload_m = Vec2(15.25, -1.0 / 3.0);
  site.robot.capacity = 12;
  site.colours.ball = {1, 2, 3};
  site.reference_balls[0].name = "it's: a ball";
  site.cameras[0].name = "camera 'north'";
  site.cameras[1].source = {CameraSource::Kind::device, {}, 2, {}};
  site.cameras[2].source = {CameraSource::Kind::url, {}, 0, "rtsp://10.0.0.9/stream"};
  site.cameras[3].position_hint_m.reset();
  const std::string text = site_file_text(site);
  const Site back = parse_site(text, kExample);
  EXPECT_EQ(back.court.fence_lane_m, site.court.fence_lane_m);
  EXPECT_EQ(back.ball_radius_m, site.ball_radius_m);
  EXPECT_EQ(back.robot.unload_m, site.robot.unload_m);
  EXPECT_EQ(back.robot.capacity, 12);
  EXPECT_EQ(back.colours.ball.bgr(), cv::Vec3b(3, 2, 1));
  EXPECT_EQ(back.reference_balls[0].name, "it's: a ball");
  EXPECT_EQ(back.reference_balls[5].floor_position_m, site.reference_balls[5].floor_position_m);
  EXPECT_EQ(back.cameras[0].name, "camera 'north'");
  EXPECT_EQ(back.cameras[0].source.path, site.cameras[0].source.path);
  EXPECT_EQ(back.cameras[0].calibration_file, site.cameras[0].calibration_file);
  EXPECT_EQ(back.cameras[1].source.kind, CameraSource::Kind::device);
  EXPECT_EQ(back.cameras[1].source.device, 2);
  EXPECT_EQ(back.cameras[2].source.url, "rtsp://10.0.0.9/stream");
  EXPECT_EQ(back.cameras[0].position_hint_m, site.cameras[0].position_hint_m);
  EXPECT_FALSE(back.cameras[3].position_hint_m.has_value());
  EXPECT_EQ(site_file_text(back), text);  // and nothing else changed
}

// A site made in code (the simulator's) has no files: its cameras get names that parse.
TEST(SiteText, ASiteWithoutFilesStillReads) {
  Site site = read_site(kExample);
  for (SiteCamera& camera : site.cameras) {
    camera.calibration_file.clear();
    camera.source = {};
  }
  const Site back = parse_site(site_file_text(site), "replay/site.yml");
  EXPECT_EQ(back.cameras[0].calibration_file, "replay/" + site.cameras[0].name + ".yml");
}

}  // namespace
}  // namespace ballsight
