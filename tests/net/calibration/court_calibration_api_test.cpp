#include "ballsight/net/calibration/court_calibration_api.hpp"

#include <gtest/gtest.h>

#include "ballsight/camera/camera_file.hpp"
#include "ballsight/camera/image_file.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/detect/ball_colours.hpp"
#include "ballsight/sim/court_renderer.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "ballsight/sim/court_scenario.hpp"
#include "example_site.hpp"
#include "net/api_error.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

using test::expect_error;

using nlohmann::json;

using test::kExampleSite;

// The example site (the simulator's court and reference balls), its cameras' frames rendered
// from a simulated scene, each camera's true intrinsics in a calibration file of a temporary
// folder. Camera 3 has delivered no frame yet.
struct CourtFixture {
  static const std::vector<cv::Mat>& rendered(const sim::CourtRig& rig,
                                              const sim::CourtScene& scene) {
    static const std::vector<cv::Mat> frames = [&] {
      std::vector<cv::Mat> out;
      for (std::size_t c = 0; c < 3; ++c)
        out.push_back(sim::CourtRenderer(rig.cameras[c], rig.court).render(scene, 2).bgr);
      out.emplace_back();
      return out;
    }();
    return frames;
  }

  test::TempDir dir;
  sim::CourtRig rig = sim::make_court_rig({}, {}, 2);
  sim::CourtScene scene = sim::make_court_scene(rig.court, {}, 2);
  const std::vector<cv::Mat>& frames = rendered(rig, scene);
  int saved = 0;  // calls of on_saved
  std::unique_ptr<CourtCalibrationApi> api;

  explicit CourtFixture(bool write_files = true) {
    CourtCalibrationApiOptions o;
    o.site = read_site(kExampleSite.string());
    for (std::size_t c = 0; c < rig.cameras.size(); ++c) {
      CameraCalibration calibration;
      calibration.intrinsics = rig.cameras[c].camera.params();
      o.site.cameras[c].calibration_file = dir / ("cam" + std::to_string(c) + ".yml");
      write_camera_file(o.site.cameras[c].calibration_file, calibration);
      o.intrinsics.push_back(calibration.intrinsics);
    }
    o.latest_frame = [this](std::size_t c) -> std::optional<cv::Mat> {
      if (frames[c].empty()) return std::nullopt;
      return frames[c];
    };
    o.write_files = write_files;
    if (write_files) o.on_saved = [this] { ++saved; };
    api = std::make_unique<CourtCalibrationApi>(std::move(o));
  }

  ApiResponse call(const std::string& method, const std::string& target,
                   const std::string& body = "", bool authorized = false) {
    return api->handle({method, target, body, authorized});
  }
  json call_json(const std::string& method, const std::string& target, const std::string& body,
                 int status, bool authorized = false) {
    const ApiResponse r = call(method, target, body, authorized);
    EXPECT_EQ(r.status, status) << method << " " << target << ": " << r.body;
    return json::parse(r.body, nullptr, false);
  }
  std::string still(const std::string& camera) {
    return call_json("POST", "/api/v1/court-calibration/stills", json{{"camera", camera}}.dump(),
                     201)["still"];
  }
};

const json& reference(const json& pose, const std::string& name) {
  for (const json& r : pose["references"])
    if (r["name"] == name) return r;
  throw std::runtime_error("no reference " + name);
}

TEST(CourtCalibrationApi, StillsPosesAndTheCalibrationFile) {
  CourtFixture f;
  const json site = f.call_json("GET", "/api/v1/court-calibration/site", "", 200);
  EXPECT_EQ(site["cameras"].size(), 4u);
  EXPECT_EQ(site["references"].size(), 12u);
  EXPECT_EQ(site["writes_files"], true);

  const std::string id = f.still("ne");
  const ApiResponse png = f.call("GET", "/api/v1/court-calibration/stills/" + id);
  ASSERT_EQ(png.status, 200);
  EXPECT_EQ(png.content_type, "image/png");
  const cv::Mat decoded = decode_image_bgr(png.body, "still");
  EXPECT_EQ(cv::norm(decoded, f.frames[0], cv::NORM_INF), 0.0);

  const std::string pose_path = "/api/v1/court-calibration/stills/" + id + "/pose";
  const json pose = f.call_json("POST", pose_path, "{}", 200);
  EXPECT_GE(pose["matched"].get<int>(), 6);
  EXPECT_LT(pose["rms_px"].get<double>(), 0.3);
  const Vec3 truth = f.rig.cameras[0].center_in_field();
  const json& at = pose["camera_position_m"];
  EXPECT_LT((Vec3(at["x"], at["y"], at["z"]) - truth).norm(), 0.03);
  int found = 0;
  for (const json& r : pose["references"]) {
    if (r["state"] != "found") continue;
    ++found;
    EXPECT_LT(r["residual_px"].get<double>(), 1.0) << r;
    const double dx = r["seen"]["x_px"].get<double>() - r["projected"]["x_px"].get<double>();
    const double dy = r["seen"]["y_px"].get<double>() - r["projected"]["y_px"].get<double>();
    EXPECT_NEAR(std::hypot(dx, dy), r["residual_px"].get<double>(), 1e-9);
  }
  EXPECT_EQ(found, pose["matched"].get<int>());

  // The YAML download: the calibration file with this pose, as the file format reads it.
  const ApiResponse yaml = f.call("POST", pose_path + "?format=yaml", "{}");
  ASSERT_EQ(yaml.status, 200);
  const CameraCalibration file = parse_camera_file(yaml.body, "download").calibration;
  ASSERT_TRUE(file.extrinsics);
  EXPECT_LT((file.extrinsics->camera_from_field.inverse().translation - truth).norm(), 0.03);
  EXPECT_EQ(file.extrinsics->reference_count, pose["matched"].get<int>());

  // Saving needs the token; then the camera's file holds the pose.
  const std::string save = "/api/v1/court-calibration/stills/" + id + "/calibration";
  const std::string before = read_file(f.dir / "cam0.yml");
  expect_error(f.call("PUT", save, "{}"), 401, "headers");
  EXPECT_EQ(read_file(f.dir / "cam0.yml"), before);
  EXPECT_EQ(f.saved, 0);
  const json saved = f.call_json("PUT", save, "{}", 200, true);
  EXPECT_EQ(saved["written"], (f.dir / "cam0.yml").string());
  EXPECT_EQ(saved["applied"], true);
  EXPECT_EQ(f.saved, 1);  // the running service was told
  EXPECT_EQ(read_file(f.dir / "cam0.yml"), yaml.body);
}

TEST(CourtCalibrationApi, AbsentAndPlacedBallsAreTheUsersWord) {
  CourtFixture f;
  const std::string path = "/api/v1/court-calibration/stills/" + f.still("se") + "/pose";
  const json pose = f.call_json("POST", path, "{}", 200);
  std::vector<json> found;
  for (const json& r : pose["references"])
    if (r["state"] == "found") found.push_back(r);
  ASSERT_GE(found.size(), 6u);
  const std::string gone = found[0]["name"], moved = found[1]["name"];
  const double x = found[1]["seen"]["x_px"].get<double>() + 2.0;
  const double y = found[1]["seen"]["y_px"].get<double>();
  const json body{{"absent", {gone}},
                  {"placed", {{{"reference", moved}, {"x_px", x}, {"y_px", y}}}}};
  const json corrected = f.call_json("POST", path, body.dump(), 200);
  EXPECT_EQ(corrected["matched"], pose["matched"].get<int>() - 1);
  EXPECT_EQ(reference(corrected, gone)["state"], "absent");
  EXPECT_TRUE(reference(corrected, gone)["seen"].is_null());
  const json& placed = reference(corrected, moved);
  EXPECT_EQ(placed["state"], "placed");
  EXPECT_EQ(placed["seen"]["x_px"], x);
  // The 2 px the click was off shows in its residual (in part: the pose leans towards it).
  EXPECT_GT(placed["residual_px"].get<double>(), 0.3);
  EXPECT_LT(corrected["rms_px"].get<double>(), 1.0);

  // Names the site has not, a ball named twice, malformed corrections.
  expect_error(f.call("POST", path, R"({"absent": ["centre court"]})"), 422, "body.absent[0]");
  expect_error(f.call("POST", path, R"({"placed": [{"reference": "nope", "x_px": 1, "y_px": 2}]})"),
               422, "body.placed[0].reference");
  expect_error(
      f.call("POST", path,
             json{{"absent", {gone}}, {"placed", {{{"reference", gone}, {"x_px", 1}, {"y_px", 2}}}}}
                 .dump()),
      422, "absent");
  expect_error(f.call("POST", path, R"({"placed": [{"reference": "singles_ne"}]})"), 422,
               "body.placed[0].x_px");
  expect_error(f.call("POST", path, R"({"absent": "singles_ne"})"), 400, "body.absent");
  expect_error(
      f.call("POST", path, R"({"placed": [{"reference": "singles_ne", "x_px": -3, "y_px": 2}]})"),
      422, "body.placed[0]");
  expect_error(f.call("POST", path,
                      R"({"placed": [{"reference": "singles_ne", "x_px": 1e300, "y_px": 2}]})"),
               422, "body.placed[0]");
  expect_error(f.call("POST", path + "?format=xml", "{}"), 400, "query format");
}

TEST(CourtCalibrationApi, TooFewBallsIsAnErrorAndNoFileIsWritten) {
  CourtFixture f;
  const std::string id = f.still("sw");
  const json pose =
      f.call_json("POST", "/api/v1/court-calibration/stills/" + id + "/pose", "{}", 200);
  json absent = json::array();
  int kept = 0;
  for (const json& r : pose["references"])
    if (r["state"] == "found" && ++kept > 3) absent.push_back(r["name"]);
  const std::string before = read_file(f.dir / "cam2.yml");
  const ApiResponse r = f.call("PUT", "/api/v1/court-calibration/stills/" + id + "/calibration",
                               json{{"absent", absent}}.dump(), true);
  EXPECT_EQ(r.status, 422) << r.body;
  EXPECT_NE(r.body.find("found 3 of 12"), std::string::npos) << r.body;
  EXPECT_EQ(read_file(f.dir / "cam2.yml"), before);
}

TEST(CourtCalibrationApi, AColourModelFromClickedBallPixels) {
  CourtFixture f;
  const std::string id = f.still("ne");
  // The nearest tennis ball the camera sees, clicked at its centre.
  const sim::CourtCamera& camera = f.rig.cameras[0];
  std::optional<Vec2> click;
  double nearest = 1e9;
  for (const sim::SceneSphere& b : f.scene.balls) {
    if (b.kind != sim::ObjectKind::tennis_ball) continue;
    const double d = (b.center_in_field - camera.center_in_field()).norm();
    const auto p = camera.camera.project(camera.camera_from_field * b.center_in_field);
    if (p && camera.camera.in_image(*p) && d < nearest) {
      nearest = d;
      click = p;
    }
  }
  ASSERT_TRUE(click);
  const std::string path = "/api/v1/court-calibration/stills/" + id + "/colours";
  const json body{{"clicks", {{{"x_px", click->x()}, {"y_px", click->y()}}}}};
  const json learned = f.call_json("POST", path, body.dump(), 200);
  const BallColours colours = ball_colours_from_json(learned["colours"], "answer");
  EXPECT_GE(colours.colours.size(), 1u);
  EXPECT_TRUE(learned["balls"].is_array());
  const ApiResponse file = f.call("POST", path + "?format=file", body.dump());
  ASSERT_EQ(file.status, 200);
  EXPECT_EQ(json::parse(file.body), learned["colours"]);

  expect_error(f.call("POST", path, R"({"clicks": [{"x_px": -5, "y_px": 3}]})"), 422, "click 1");
  expect_error(f.call("POST", path, R"({"clicks": []})"), 400, "body.clicks");
  expect_error(f.call("POST", path, "{}"), 400, "body.clicks");
  expect_error(f.call("POST", path + "?format=png", body.dump()), 400, "query format");
}

TEST(CourtCalibrationApi, BadRequestsNameWhatIsWrong) {
  CourtFixture f;
  expect_error(f.call("POST", "/api/v1/court-calibration/stills", R"({"camera": "centre"})"), 404,
               "body.camera");
  expect_error(f.call("POST", "/api/v1/court-calibration/stills", R"({"camera": "nw"})"), 409,
               "camera nw");
  expect_error(f.call("POST", "/api/v1/court-calibration/stills", "not json"), 400, "body");
  expect_error(f.call("POST", "/api/v1/court-calibration/stills", "{}"), 400, "body.camera");
  expect_error(f.call("GET", "/api/v1/court-calibration/stills/99"), 404, "still 99");
  expect_error(f.call("POST", "/api/v1/court-calibration/stills/99/pose", "{}"), 404, "still 99");
  expect_error(f.call("DELETE", "/api/v1/court-calibration/site"), 405,
               "/api/v1/court-calibration/site");
  expect_error(f.call("GET", "/api/v1/court-calibration/elsewhere"), 404,
               "/api/v1/court-calibration/elsewhere");

  // A service without calibration files (the simulated court) offers the download only.
  CourtFixture sim(false);
  const std::string id = sim.still("ne");
  EXPECT_EQ(sim.call_json("GET", "/api/v1/court-calibration/site", "",
                          200)["cameras"][0]["calibration_file"],
            nullptr);
  expect_error(
      sim.call("PUT", "/api/v1/court-calibration/stills/" + id + "/calibration", "{}", true), 409,
      "calibration");
}

}  // namespace
}  // namespace ballsight
