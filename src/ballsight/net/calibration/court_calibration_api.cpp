#include "ballsight/net/calibration/court_calibration_api.hpp"

#include <algorithm>
#include <deque>
#include <mutex>

#include "ballsight/camera/camera_file.hpp"
#include "ballsight/camera/image_file.hpp"
#include "ballsight/core/json_fields.hpp"
#include "ballsight/detect/ball_colour_learning.hpp"
#include "ballsight/detect/photo_balls.hpp"
#include "ballsight/net/api_request.hpp"
#include "ballsight/pipeline/court_calibration.hpp"

namespace ballsight {
namespace {

using nlohmann::json;

constexpr const char* kPrefix = "/api/v1/court-calibration/";

json pixel_json(const Vec2& p) {
  return {{"x_px", p.x()}, {"y_px", p.y()}};
}

Vec2 pixel_of(const json& object, const std::string& where) {
  return {json_number(object, "x_px", where), json_number(object, "y_px", where)};
}

/// A camera's frame kept while the user works on it.
struct Still {
  std::uint64_t id = 0;
  std::size_t camera = 0;
  cv::Mat bgr;
  std::string png;
};

/// The reference's index by its name; a 422 naming `where` when the site has none of that name.
std::size_t reference_index(const std::vector<ReferencePoint>& references, const std::string& name,
                            const std::string& where) {
  const auto it = std::find_if(references.begin(), references.end(),
                               [&](const ReferencePoint& r) { return r.name == name; });
  if (it == references.end()) api_fail(422, "no reference ball '" + name + "' on this site", where);
  return static_cast<std::size_t>(it - references.begin());
}

/// {"placed": [{"reference", "x_px", "y_px"}], "absent": [name, ...]}, both optional; a placed
/// pixel lies in the image.
ReferenceCorrections corrections_of(const json& body, const std::vector<ReferencePoint>& references,
                                    const PinholeCamera& camera) {
  ReferenceCorrections out;
  if (const auto placed = body.find("placed"); placed != body.end()) {
    if (!placed->is_array()) api_fail(400, "expected a list", "body.placed");
    for (std::size_t i = 0; i < placed->size(); ++i) {
      const std::string where = "body.placed[" + std::to_string(i) + "]";
      const json& p = (*placed)[i];
      const Vec2 pixel = pixel_of(p, where);
      if (!camera.in_image(pixel)) {
        api_fail(422,
                 "lies outside the " + std::to_string(camera.width()) + "x" +
                     std::to_string(camera.height()) + " image",
                 where);
      }
      out.placed.push_back(
          {reference_index(references, json_string(p, "reference", where), where + ".reference"),
           pixel});
    }
  }
  if (const auto absent = body.find("absent"); absent != body.end()) {
    if (!absent->is_array()) api_fail(400, "expected a list of names", "body.absent");
    for (std::size_t i = 0; i < absent->size(); ++i) {
      const std::string where = "body.absent[" + std::to_string(i) + "]";
      if (!(*absent)[i].is_string()) api_fail(400, "expected a reference ball's name", where);
      out.absent.push_back(reference_index(references, (*absent)[i].get<std::string>(), where));
    }
  }
  out.validate(references.size());
  return out;
}

/// Every reference ball: where it was seen ("found" by the blobs, "placed" by hand), where the
/// pose projects it, and the residual; "absent" (marked so) or "missing" (not seen) else.
json pose_json(const CameraPoseReport& report, const ReferenceCorrections& corrections,
               const PinholeCamera& camera) {
  const ReferencePose& pose = report.pose;
  json references = json::array();
  for (std::size_t r = 0; r < report.references.size(); ++r) {
    const ReferencePoint& ref = report.references[r];
    json j{{"name", ref.name},      {"x_m", ref.p_in_field.x()}, {"y_m", ref.p_in_field.y()},
           {"state", "missing"},    {"seen", nullptr},           {"projected", nullptr},
           {"residual_px", nullptr}};
    if (const auto p = camera.project(pose.camera_from_field * ref.p_in_field)) {
      j["projected"] = pixel_json(*p);
    }
    if (std::find(corrections.absent.begin(), corrections.absent.end(), r) !=
        corrections.absent.end()) {
      j["state"] = "absent";
    }
    for (std::size_t m = 0; m < pose.matches.size(); ++m) {
      if (pose.matches[m].reference != r) continue;
      const bool placed = std::any_of(corrections.placed.begin(), corrections.placed.end(),
                                      [&](const auto& p) { return p.first == r; });
      j["state"] = placed ? "placed" : "found";
      j["seen"] = pixel_json(pose.matched_px[m]);
      j["residual_px"] = pose.matches[m].residual_px;
    }
    references.push_back(j);
  }
  json candidates = json::array();
  for (const Vec2& c : report.candidates_px) candidates.push_back(pixel_json(c));
  const Vec3 center = pose.camera_from_field.inverse().translation;
  return {{"camera", report.camera},
          {"blobs", candidates},
          {"references", references},
          {"matched", pose.matches.size()},
          {"rms_px", pose.rms_px},
          {"max_px", pose.max_px},
          {"camera_position_m", {{"x", center.x()}, {"y", center.y()}, {"z", center.z()}}}};
}

json balls_json(const std::vector<PhotoBall>& balls) {
  json list = json::array();
  for (const PhotoBall& b : balls) {
    json j = pixel_json(b.center_px);
    j["radius_px"] = b.radius_px;
    j["score"] = b.score;
    list.push_back(j);
  }
  return list;
}

}  // namespace

struct CourtCalibrationApi::Impl {
  CourtCalibrationApiOptions options;
  std::vector<ReferencePoint> references;
  std::mutex mutex;  // stills, next_id
  std::deque<std::shared_ptr<const Still>> stills;
  std::uint64_t next_id = 1;

  std::size_t camera_index(const std::string& name, const std::string& where) const {
    const auto& cameras = options.site.cameras;
    const auto it = std::find_if(cameras.begin(), cameras.end(),
                                 [&](const SiteCamera& c) { return c.name == name; });
    if (it == cameras.end()) api_fail(404, "no camera '" + name + "' on this site", where);
    return static_cast<std::size_t>(it - cameras.begin());
  }

  std::shared_ptr<const Still> still(const std::string& id) {
    std::lock_guard lock(mutex);
    return item_by_id(stills, id, "still",
                      "no such still (stills are forgotten after " +
                          std::to_string(options.max_stills) + " newer ones)");
  }

  ApiResponse site() const {
    json cameras = json::array();
    for (std::size_t k = 0; k < options.site.cameras.size(); ++k) {
      const SiteCamera& c = options.site.cameras[k];
      cameras.push_back(
          {{"name", c.name},
           {"width", options.intrinsics[k].width},
           {"height", options.intrinsics[k].height},
           {"calibration_file",
            options.write_files ? json(c.calibration_file.string()) : json(nullptr)}});
    }
    json balls = json::array();
    for (const ReferencePoint& r : references)
      balls.push_back({{"name", r.name},
                       {"x_m", r.p_in_field.x()},
                       {"y_m", r.p_in_field.y()},
                       {"z_m", r.p_in_field.z()}});
    return json_answer(
        200, {{"cameras", cameras}, {"references", balls}, {"writes_files", options.write_files}});
  }

  ApiResponse take_still(const ApiRequest& request) {
    const json body = parse_body(request.body);
    const auto name = body.find("camera");
    if (name == body.end() || !name->is_string())
      api_fail(400, "expected a camera's name", "body.camera");
    auto s = std::make_shared<Still>();
    s->camera = camera_index(name->get<std::string>(), "body.camera");
    const std::optional<cv::Mat> frame = options.latest_frame(s->camera);
    if (!frame || frame->empty()) {
      api_fail(409, "no frame from this camera yet",
               "camera " + options.site.cameras[s->camera].name);
    }
    s->bgr = *frame;
    s->png = png_bytes(s->bgr, "still");
    std::lock_guard lock(mutex);
    s->id = next_id++;
    stills.push_back(s);
    if (stills.size() > options.max_stills) stills.pop_front();
    return json_answer(201, {{"still", std::to_string(s->id)},
                             {"camera", options.site.cameras[s->camera].name},
                             {"width", s->bgr.cols},
                             {"height", s->bgr.rows}});
  }

  /// The still's pose under the body's corrections, and the calibration it makes.
  std::pair<CameraPoseReport, ReferenceCorrections> pose(const Still& s,
                                                         const ApiRequest& request) {
    const json body = request.body.empty() ? json::object() : parse_body(request.body);
    const ReferenceCorrections corrections =
        corrections_of(body, references, PinholeCamera(options.intrinsics[s.camera]));
    const SiteCamera& camera = options.site.cameras[s.camera];
    CameraCalibration calibration;
    calibration.intrinsics = options.intrinsics[s.camera];
    if (options.write_files) calibration = read_camera_file(camera.calibration_file);
    return {calibrate_site_camera(options.site, camera, s.bgr, "still " + std::to_string(s.id),
                                  calibration, {}, corrections),
            corrections};
  }

  ApiResponse pose_answer(const Still& s, const ApiRequest& request, const std::string& query) {
    const std::string format = query_choice(query, "format", {"json", "yaml"});
    const auto [report, corrections] = pose(s, request);
    if (format == "yaml") return bytes_answer(camera_file_text(report.calibration), "text/yaml");
    return json_answer(
        200, pose_json(report, corrections, PinholeCamera(report.calibration.intrinsics)));
  }

  ApiResponse save(const Still& s, const ApiRequest& request) {
    require_write(request);
    if (!options.write_files) {
      api_fail(409, "this service has no calibration files (the simulated court): download it",
               "calibration");
    }
    const auto [report, corrections] = pose(s, request);
    write_camera_file(report.calibration_file, report.calibration);
    if (options.on_saved) options.on_saved();
    json answer = pose_json(report, corrections, PinholeCamera(report.calibration.intrinsics));
    answer["written"] = report.calibration_file.string();
    answer["applied"] = static_cast<bool>(options.on_saved);
    return json_answer(200, answer);
  }

  ApiResponse colours(const Still& s, const ApiRequest& request, const std::string& query) {
    const std::string format = query_choice(query, "format", {"json", "file"});
    const json body = parse_body(request.body);
    const auto list_at = body.find("clicks");
    if (list_at == body.end() || !list_at->is_array() || list_at->empty())
      api_fail(400, "expected a list of pixels", "body.clicks");
    const json& list = *list_at;
    std::vector<Vec2> clicks;
    for (std::size_t i = 0; i < list.size(); ++i)
      clicks.push_back(pixel_of(list[i], "body.clicks[" + std::to_string(i) + "]"));
    PhotoBallOptions detector;
    detector.colours = learn_ball_colours(s.bgr, clicks);
    if (format == "file") {
      return bytes_answer(ball_colours_json(detector.colours).dump(2) + "\n", "application/json");
    }
    return json_answer(200, {{"colours", ball_colours_json(detector.colours)},
                             {"balls", balls_json(PhotoBallDetector(detector).detect(s.bgr))}});
  }

  ApiResponse route(const ApiRequest& request, const std::vector<std::string>& parts,
                    const std::string& query) {
    const auto of_still = [&](auto answer) {
      return [this, &parts, answer] { return answer(*still(parts[1])); };
    };
    return dispatch(request, parts,
                    {{1, "site", nullptr, "GET", [&] { return site(); }},
                     {1, "stills", nullptr, "POST", [&] { return take_still(request); }},
                     {2, "stills", nullptr, "GET",
                      of_still([](const Still& s) { return bytes_answer(s.png, "image/png"); })},
                     {3, "stills", "pose", "POST",
                      of_still([&](const Still& s) { return pose_answer(s, request, query); })},
                     {3, "stills", "calibration", "PUT",
                      of_still([&](const Still& s) { return save(s, request); })},
                     {3, "stills", "colours", "POST",
                      of_still([&](const Still& s) { return colours(s, request, query); })}});
  }
};

CourtCalibrationApi::CourtCalibrationApi(CourtCalibrationApiOptions options)
    : impl_(std::make_unique<Impl>()) {
  require(options.intrinsics.size() == options.site.cameras.size(), "court calibration",
          "intrinsics for " + std::to_string(options.intrinsics.size()) + " of " +
              std::to_string(options.site.cameras.size()) + " cameras");
  require(options.site.cameras.empty() || options.latest_frame, "court calibration",
          "no source of the cameras' frames");
  require(options.max_stills >= 1, "max_stills", "must be at least 1");
  impl_->references = site_references(options.site);
  impl_->options = std::move(options);
}

CourtCalibrationApi::~CourtCalibrationApi() = default;

void CourtCalibrationApi::register_routes(ApiRoutes& routes) {
  routes.add({.prefix = kPrefix,
              .handler = [this](const ApiRequest& request) { return handle(request); },
              .runs_long = true});
}

ApiResponse CourtCalibrationApi::handle(const ApiRequest& request) {
  const RequestTarget target = split_target(request.target);
  return answer_or_error(
      [&] { return impl_->route(request, path_parts(target.path, kPrefix), target.query); });
}

}  // namespace ballsight
