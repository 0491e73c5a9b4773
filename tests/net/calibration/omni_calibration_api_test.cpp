#include "ballsight/net/calibration/omni_calibration_api.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "ballsight/calib/sample_csv.hpp"
#include "ballsight/camera/ground_map_io.hpp"
#include "ballsight/camera/image_file.hpp"
#include "ballsight/camera/iris_lut.hpp"
#include "ballsight/core/angle.hpp"
#include "ballsight/pipeline/omni_calibration.hpp"
#include "ballsight/sim/omni_dataset.hpp"
#include "net/api_error.hpp"
#include "wait_until.hpp"

namespace ballsight {
namespace {

using test::expect_error;

using nlohmann::json;

const cv::Mat& calibration_frame() {
  static const cv::Mat frame = sim::render_calibration_frame({});
  return frame;
}

struct OmniFixture {
  OmniCalibrationApi api{[] {
    OmniCalibrationOptions o;
    o.simulated_frame = [] { return calibration_frame(); };
    return o;
  }()};

  ApiResponse call(const std::string& method, const std::string& target,
                   const std::string& body = "") {
    return api.handle({method, target, body, false});
  }
  json call_json(const std::string& method, const std::string& target, const std::string& body,
                 int status) {
    const ApiResponse r = call(method, target, body);
    EXPECT_EQ(r.status, status) << method << " " << target << ": " << r.body;
    return json::parse(r.body, nullptr, false);
  }
};

TEST(OmniCalibrationApi, ABadUploadIsRefusedAndChangesNothing) {
  OmniFixture f;
  expect_error(f.call("POST", "/api/v1/omni/frames", "hello, not an image"), 415, "body");
  expect_error(f.call("POST", "/api/v1/omni/frames", "\x89PNG\r\n\x1a\ntruncated"), 422, "body");
  // A PNG header declaring 20000 x 20000 pixels (a few bytes that would decode to 1.2 GB):
  // refused before decoding.
  std::string huge = std::string("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR", 16);
  huge += std::string("\0\0\x4e\x20\0\0\x4e\x20\x08\x02\0\0\0", 13);
  const ApiResponse too_large = f.call("POST", "/api/v1/omni/frames", huge);
  expect_error(too_large, 413, "body");
  EXPECT_NE(too_large.body.find("20000x20000"), std::string::npos) << too_large.body;
  expect_error(f.call("POST", "/api/v1/omni/frames", R"({"file": "../etc/passwd"})"), 404,
               "body.file");
  // No frame was kept: the first good one gets the first id.
  const json frame = f.call_json("POST", "/api/v1/omni/frames", R"({"simulated": true})", 201);
  EXPECT_EQ(frame["frame"], "1");
  EXPECT_EQ(frame["width"], 640);
  EXPECT_EQ(frame["source"], "simulated");
  const ApiResponse png = f.call("GET", "/api/v1/omni/frames/1");
  EXPECT_EQ(png.content_type, "image/png");
  const cv::Mat decoded = decode_image_bgr(png.body, "frame 1");
  EXPECT_EQ(cv::norm(decoded, calibration_frame(), cv::NORM_INF), 0.0);
}

TEST(OmniCalibrationApi, UploadedFrameGetsTheMirrorRimAsCentre) {
  OmniFixture f;
  const json frame =
      f.call_json("POST", "/api/v1/omni/frames", png_bytes(calibration_frame(), "frame"), 201);
  EXPECT_EQ(frame["source"], "upload");
  ASSERT_TRUE(frame["rim"].is_object()) << frame;
  // The simulated rig's principal point is 3-7 px off the image centre (319.5, 239.5) and its
  // axis tilted 1-2 deg: the rim's centre is a suggestion within a few pixels.
  EXPECT_NEAR(frame["rim"]["x_px"].get<double>(), 319.5, 12.0);
  EXPECT_NEAR(frame["rim"]["y_px"].get<double>(), 239.5, 12.0);
}

TEST(OmniCalibrationApi, MarkersFitAndTablesAreTheLibrarys) {
  OmniFixture f;
  f.call_json("POST", "/api/v1/omni/frames", R"({"simulated": true})", 201);
  const json center = {{"x_px", 319.5}, {"y_px", 239.5}};
  const json found =
      f.call_json("POST", "/api/v1/omni/frames/1/markers", json{{"center", center}}.dump(), 200);
  const json& markers = found["markers"];
  EXPECT_EQ(found["layout_markers"], 324);
  EXPECT_GE(markers.size(), 300u) << found["blobs"];

  // The export is the samples CSV of the points; imported back, the same points.
  const ApiResponse csv =
      f.call("POST", "/api/v1/omni/samples", json{{"center", center}, {"points", markers}}.dump());
  ASSERT_EQ(csv.status, 200) << csv.body;
  const std::vector<PolarSample> samples = parse_polar_samples_csv(csv.body, "export");
  ASSERT_EQ(samples.size(), markers.size());
  const json imported =
      f.call_json("POST", "/api/v1/omni/points?center=319.5,239.5", csv.body, 200);
  for (std::size_t i = 0; i < markers.size(); ++i) {
    EXPECT_NEAR(imported["points"][i]["x_px"], markers[i]["x_px"], 1e-9);
    EXPECT_NEAR(imported["points"][i]["distance_cm"], markers[i]["distance_cm"], 1e-12);
    EXPECT_NEAR(imported["points"][i]["bearing_deg"], markers[i]["bearing_deg"], 1e-9);
  }

  const json body = {{"method", "poly"},
                     {"center", center},
                     {"image", {{"width", 640}, {"height", 480}}},
                     {"points", markers}};
  json fit = f.call_json("POST", "/api/v1/omni/fits", body.dump(), 202);
  EXPECT_EQ(fit["state"], "running");
  expect_error(
      f.call("GET", "/api/v1/omni/fits/" + fit["fit"].get<std::string>() + "/table?format=png"),
      400, "query format");
  const std::string id = fit["fit"];
  const auto started = std::chrono::steady_clock::now();
  while (fit["state"] == "running" &&
         std::chrono::steady_clock::now() - started < std::chrono::minutes(2)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    fit = f.call_json("GET", "/api/v1/omni/fits/" + id, "", 200);
  }
  ASSERT_EQ(fit["state"], "done") << fit;
  EXPECT_EQ(fit["residuals"].size(), markers.size());
  EXPECT_EQ(fit["curves"].size(), 12u);

  // The table is the library's on the exported samples, byte for byte, in both formats.
  const OmniCalibration expected =
      calibrate_omni(OmniMethod::kPoly, samples, {640, 480, Vec2(319.5, 239.5)});
  for (std::size_t i = 0; i < markers.size(); ++i) {
    EXPECT_DOUBLE_EQ(fit["residuals"][i]["distance_error_cm"].get<double>(),
                     expected.residuals[i].distance_error_cm);
  }
  const ApiResponse table = f.call("GET", "/api/v1/omni/fits/" + id + "/table");
  EXPECT_EQ(table.content_type, "application/octet-stream");
  EXPECT_TRUE(table.body == ground_map_bytes(expected.table));
  const ApiResponse iris = f.call("GET", "/api/v1/omni/fits/" + id + "/table?format=iris");
  EXPECT_TRUE(iris.body == iris_lut_bytes(iris_px2cm_from_ground_map(expected.table)));

  // Places from the fit: where it errs by less than half the rings' spacing, the markers' own
  // rings (the paper's polynomial around the image's centre is that good out to about 3 m).
  json pixels = json::array();
  std::vector<std::size_t> near;
  for (std::size_t i = 0; i < markers.size(); ++i) {
    if (std::abs(expected.residuals[i].distance_error_cm) >= 20.0) continue;
    near.push_back(i);
    pixels.push_back({{"x_px", markers[i]["x_px"]}, {"y_px", markers[i]["y_px"]}});
  }
  ASSERT_GE(near.size(), 100u);
  const json places =
      f.call_json("POST", "/api/v1/omni/places",
                  json{{"center", center}, {"points", pixels}, {"fit", id}}.dump(), 200);
  for (std::size_t k = 0; k < near.size(); ++k) {
    EXPECT_NEAR(places["points"][k]["distance_cm"], markers[near[k]]["distance_cm"], 1e-9) << k;
    EXPECT_NEAR(wrap_deg_180(places["points"][k]["bearing_deg"].get<double>() -
                             markers[near[k]]["bearing_deg"].get<double>()),
                0.0, 1e-6)
        << k;
  }
}

TEST(OmniCalibrationApi, BadRequestsNameWhatIsWrong) {
  OmniFixture f;
  expect_error(f.call("POST", "/api/v1/omni/points?center=1,2", "theta_deg,radius_px\n1,2\n"), 422,
               "samples CSV:1:1");
  expect_error(f.call("POST", "/api/v1/omni/points", "theta_deg,radius_px,distance_cm\n"), 400,
               "query");
  expect_error(f.call("POST", "/api/v1/omni/fits",
                      R"({"method": "spline", "center": {"x_px": 1, "y_px": 1},
                          "image": {"width": 64, "height": 64}, "points": []})"),
               422, "body.method");
  expect_error(f.call("POST", "/api/v1/omni/places",
                      R"({"center": {"x_px": 1, "y_px": 1}, "points": [{"x_px": 2}]})"),
               422, "body.points[0].y_px");
  expect_error(f.call("GET", "/api/v1/omni/fits/9/table"), 404, "fit 9");
  expect_error(f.call("DELETE", "/api/v1/omni/files"), 405, "/api/v1/omni/files");
  expect_error(f.call("GET", "/api/v1/omni/nothing"), 404, "/api/v1/omni/nothing");
  // A fit that cannot be made fails with the library's message.
  json fit = f.call_json("POST", "/api/v1/omni/fits",
                         R"({"method": "poly", "center": {"x_px": 32, "y_px": 32},
                             "image": {"width": 64, "height": 64},
                             "points": [{"x_px": 40, "y_px": 32, "distance_cm": 100}]})",
                         202);
  ASSERT_TRUE(test::wait_until(
      [&] {
        fit = f.call_json("GET", "/api/v1/omni/fits/" + fit["fit"].get<std::string>(), "", 200);
        return fit["state"] != "running";
      },
      std::chrono::minutes(2), std::chrono::milliseconds(10)))
      << "the fit still runs after 2 minutes";
  EXPECT_EQ(fit["state"], "failed");
  EXPECT_FALSE(fit["error"].get<std::string>().empty());
}

}  // namespace
}  // namespace ballsight
