#include "ballsight/net/calibration/omni_calibration_api.hpp"

#include <algorithm>
#include <deque>
#include <map>
#include <mutex>
#include <optional>
#include <thread>
#include <tuple>
#include <vector>

#include "ballsight/calib/sample_csv.hpp"
#include "ballsight/camera/ground_map_io.hpp"
#include "ballsight/camera/image_file.hpp"
#include "ballsight/camera/iris_lut.hpp"
#include "ballsight/core/csv_fields.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/core/json_fields.hpp"
#include "ballsight/net/api_request.hpp"
#include "ballsight/pipeline/marker_frame_samples.hpp"
#include "ballsight/pipeline/omni_calibration.hpp"

namespace ballsight {
namespace {

using nlohmann::json;

constexpr const char* kPrefix = "/api/v1/omni/";
constexpr std::size_t kMaxRunningFits = 2;

Vec2 pixel_of(const json& object, const std::string& where) {
  return {json_number(object, "x_px", where), json_number(object, "y_px", where)};
}

json pixel_json(const Vec2& p) {
  return {{"x_px", p.x()}, {"y_px", p.y()}};
}

std::vector<MarkerPoint> points_of(const json& body) {
  const json& list = json_member(body, "points", "body");
  if (!list.is_array()) api_fail(400, "expected a list", "body.points");
  std::vector<MarkerPoint> points;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string where = "body.points[" + std::to_string(i) + "]";
    MarkerPoint p{pixel_of(list[i], where), json_number(list[i], "distance_cm", where),
                  std::nullopt};
    if (const auto b = list[i].find("bearing_deg"); b != list[i].end() && !b->is_null()) {
      p.bearing_deg = json_number(list[i], "bearing_deg", where);
    }
    points.push_back(p);
  }
  return points;
}

json points_json(const std::vector<MarkerPoint>& points) {
  json list = json::array();
  for (const MarkerPoint& p : points) {
    json j = pixel_json(p.pixel);
    j["distance_cm"] = p.distance_cm;
    j["bearing_deg"] = p.bearing_deg ? json(*p.bearing_deg) : json(nullptr);
    list.push_back(j);
  }
  return list;
}

/// The member `key` of `body` when present and not null.
const json* optional_member(const json& body, const char* key) {
  const auto it = body.find(key);
  return it == body.end() || it->is_null() ? nullptr : &*it;
}

/// {"bearing_step_deg", "min_cm", "max_cm", "step_cm"}, each optional (the paper's layout).
MarkerLayout layout_of(const json& body) {
  MarkerLayout layout;
  const json* l = optional_member(body, "layout");
  if (!l) return layout;
  const std::string where = "body.layout";
  if (l->contains("bearing_step_deg"))
    layout.bearing_step_deg = json_number(*l, "bearing_step_deg", where);
  if (l->contains("min_cm")) layout.min_distance_m = 0.01 * json_number(*l, "min_cm", where);
  if (l->contains("max_cm")) layout.max_distance_m = 0.01 * json_number(*l, "max_cm", where);
  if (l->contains("step_cm")) layout.distance_step_m = 0.01 * json_number(*l, "step_cm", where);
  layout.validate();
  return layout;
}

bool is_image_upload(const std::string& body) {
  return body.starts_with("\x89PNG\r\n\x1a\n") || body.starts_with("\xff\xd8\xff");
}

struct Frame {
  std::uint64_t id = 0;
  cv::Mat bgr;
  std::string png;
  std::string source;
  std::optional<MirrorRim> rim;
};

json frame_json(const Frame& f) {
  json j{{"frame", std::to_string(f.id)},
         {"width", f.bgr.cols},
         {"height", f.bgr.rows},
         {"source", f.source},
         {"rim", nullptr}};
  if (f.rim) {
    j["rim"] = pixel_json(f.rim->center_px);
    j["rim"]["radius_px"] = f.rim->radius_px;
  }
  return j;
}

json summary_json(const ErrorSummary& s) {
  return {{"count", s.count}, {"median", s.median}, {"p95", s.p95}, {"max", s.max}};
}

/// A fit: running on its own thread until `state` leaves "running".
struct FitJob {
  std::uint64_t id = 0;
  std::mutex mutex;
  std::string state = "running";  // "running", "done", "failed"
  json result;                    // the answer of GET once done or failed
  std::unique_ptr<OmniGroundModel> model;
  std::unique_ptr<GroundMap> map;
  std::string table;  // `map` in ballsight's table format
  std::optional<std::string> iris_table;
};

json residuals_json(const std::vector<SampleResidual>& list) {
  json residuals = json::array();
  for (const SampleResidual& r : list) {
    residuals.push_back(
        {{"predicted_distance_cm", r.predicted_distance_cm},
         {"distance_error_cm", r.distance_error_cm},
         {"bearing_error_deg", r.bearing_error_deg ? json(*r.bearing_error_deg) : json(nullptr)},
         {"in_range", r.in_range}});
  }
  return residuals;
}

/// A table uploaded to check points against.
struct CheckedTable {
  std::uint64_t id = 0;
  GroundMap map;
};

json fit_result(const OmniCalibration& fit, const OmniImage& image, std::size_t samples) {
  const json residuals = residuals_json(fit.residuals);
  json curves = json::array();
  for (const RadialCurve& c : radial_curves(*fit.model)) {
    curves.push_back(
        {{"theta_deg", c.theta_deg}, {"radius_px", c.radius_px}, {"distance_cm", c.distance_cm}});
  }
  const RadiusRange range = fit.model->domain().valid_radius;
  return {{"method", std::string(fit.model->name())},
          {"image", {{"width", image.width}, {"height", image.height}}},
          {"center", pixel_json(image.center_px)},
          {"samples", samples},
          {"valid_radius", {{"min_px", range.min_px}, {"max_px", range.max_px}}},
          {"errors",
           {{"distance_cm", summary_json(fit.errors.distance_cm)},
            {"position_cm", summary_json(fit.errors.position_cm)}}},
          {"residuals", residuals},
          {"curves", curves}};
}

}  // namespace

struct OmniCalibrationApi::Impl {
  OmniCalibrationOptions options;
  std::mutex mutex;  // frames, fits, workers, next_id
  std::deque<std::shared_ptr<const Frame>> frames;
  std::deque<std::shared_ptr<FitJob>> fits;
  std::deque<std::shared_ptr<const CheckedTable>> tables;
  std::vector<std::pair<std::shared_ptr<FitJob>, std::thread>> workers;
  std::uint64_t next_id = 1;

  /// Joins the threads of fits that are over (they end right after leaving "running").
  void join_finished_workers() {
    std::erase_if(workers, [](auto& w) {
      {
        std::lock_guard l(w.first->mutex);
        if (w.first->state == "running") return false;
      }
      w.second.join();
      return true;
    });
  }

  std::shared_ptr<const Frame> frame(const std::string& id) {
    std::lock_guard lock(mutex);
    return item_by_id(frames, id, "frame",
                      "no such frame (frames are forgotten after " +
                          std::to_string(options.max_frames) + " newer ones)");
  }

  std::shared_ptr<FitJob> fit(const std::string& id) {
    std::lock_guard lock(mutex);
    return item_by_id(fits, id, "fit", "no such fit");
  }

  /// The frame a POST asks for and where it came from.
  std::pair<cv::Mat, std::string> frame_image(const std::string& body) {
    if (is_image_upload(body)) {
      if (const std::optional<cv::Size> size = declared_image_size(body);
          size && static_cast<std::size_t>(size->width) * static_cast<std::size_t>(size->height) >
                      options.max_image_pixels) {
        api_fail(413,
                 "image of " + std::to_string(size->width) + "x" + std::to_string(size->height) +
                     " pixels is larger than " + std::to_string(options.max_image_pixels),
                 "body");
      }
      return {decode_image_bgr(body, "body", std::nullopt, options.max_image_pixels), "upload"};
    }
    if (body.empty() || body.front() != '{') {
      api_fail(415, "not a PNG or JPEG image (nor a JSON request {\"file\"} or {\"simulated\"})",
               "body");
    }
    const json request = parse_body(body);
    if (request.value("simulated", false)) {
      if (!options.simulated_frame) api_fail(404, "no simulated omni robot here", "body.simulated");
      return {options.simulated_frame(), "simulated"};
    }
    const std::string name = json_string(request, "file", "body");
    if (options.frames_dir.empty()) api_fail(404, "the server offers no files", "body.file");
    const std::filesystem::path path = options.frames_dir / name;
    if (name.find('/') != std::string::npos || name.starts_with(".") ||
        !std::filesystem::is_regular_file(path)) {
      api_fail(404, "no such file in the server's folder", "body.file");
    }
    return {read_image_bgr(path), "file " + name};
  }

  ApiResponse add_frame(const ApiRequest& request) {
    auto f = std::make_shared<Frame>();
    std::tie(f->bgr, f->source) = frame_image(request.body);
    if (static_cast<std::size_t>(f->bgr.total()) > options.max_image_pixels) {
      api_fail(413, "image larger than " + std::to_string(options.max_image_pixels) + " pixels",
               "body");
    }
    f->png = png_bytes(f->bgr, "frame");
    f->rim = find_mirror_rim(f->bgr);
    std::lock_guard lock(mutex);
    f->id = next_id++;
    frames.push_back(f);
    if (frames.size() > options.max_frames) frames.pop_front();
    return json_answer(201, frame_json(*f));
  }

  ApiResponse files() const {
    json list = json::array();
    if (!options.frames_dir.empty() && std::filesystem::is_directory(options.frames_dir)) {
      std::vector<std::string> names;
      for (const auto& entry : std::filesystem::directory_iterator(options.frames_dir)) {
        const std::string ext = entry.path().extension().string();
        if (entry.is_regular_file() && (ext == ".png" || ext == ".jpg" || ext == ".jpeg"))
          names.push_back(entry.path().filename().string());
      }
      std::sort(names.begin(), names.end());
      for (const std::string& n : names) list.push_back(n);
    }
    return json_answer(200, {{"files", list}, {"simulated", bool(options.simulated_frame)}});
  }

  ApiResponse markers(const Frame& frame, const ApiRequest& request) {
    const json body = parse_body(request.body);
    const Vec2 center = pixel_of(json_member(body, "center", "body"), "body.center");
    const MarkerLayout layout = layout_of(body);
    cv::Vec3b bgr(220, 40, 220);
    if (const json* c = optional_member(body, "marker_bgr")) {
      const std::vector<double> v = json_number_array(*c, "body.marker_bgr", 3);
      for (int i = 0; i < 3; ++i) {
        if (v[i] < 0 || v[i] > 255) api_fail(400, "expected 0-255", "body.marker_bgr");
        bgr[i] = static_cast<uchar>(v[i]);
      }
    }
    const double diameter_cm = optional_member(body, "marker_diameter_cm")
                                   ? json_number(body, "marker_diameter_cm", "body")
                                   : 0.0;
    const std::vector<LayoutMarker> layout_points = markers_of_diameter(layout, 0.01 * diameter_cm);
    const MarkerFrameSamples found =
        samples_from_marker_frame(frame.bgr, layout_points, bgr, center);
    return json_answer(200, {{"markers", points_json(marker_points_of(found.samples, center))},
                             {"blobs", found.blobs},
                             {"layout_markers", layout_points.size()}});
  }

  ApiResponse places(const ApiRequest& request) {
    const json body = parse_body(request.body);
    const Vec2 center = pixel_of(json_member(body, "center", "body"), "body.center");
    const json& list = json_member(body, "points", "body");
    if (!list.is_array()) api_fail(400, "expected a list", "body.points");
    std::vector<Vec2> pixels;
    for (std::size_t i = 0; i < list.size(); ++i)
      pixels.push_back(pixel_of(list[i], "body.points[" + std::to_string(i) + "]"));
    std::shared_ptr<FitJob> job;
    if (const json* id = optional_member(body, "fit")) {
      if (!id->is_string()) api_fail(400, "expected a fit's id", "body.fit");
      job = fit(id->get<std::string>());
    }
    std::unique_lock<std::mutex> job_lock;
    const OmniGroundModel* model = nullptr;
    if (job) {
      job_lock = std::unique_lock(job->mutex);
      model = job->model.get();
    }
    return json_answer(
        200,
        {{"points", points_json(suggest_layout_places(pixels, center, layout_of(body), model))}});
  }

  ApiResponse samples_csv(const ApiRequest& request) {
    const json body = parse_body(request.body);
    const Vec2 center = pixel_of(json_member(body, "center", "body"), "body.center");
    const std::vector<MarkerPoint> points = points_of(body);
    return bytes_answer(format_polar_samples_csv(polar_samples_of(points, center)), "text/csv");
  }

  ApiResponse import_csv(const ApiRequest& request, const std::string& query) {
    const std::optional<std::string> center_text = query_text(query, "center");
    if (!center_text) api_fail(400, "missing center=X,Y", "query");
    const std::vector<CsvField> xy = split_csv_fields(*center_text);
    if (xy.size() != 2)
      api_fail(400, "expected X,Y in pixels, got '" + *center_text + "'", "query center");
    const Vec2 center(csv_number(xy[0], "query center"), csv_number(xy[1], "query center"));
    const std::vector<PolarSample> samples = parse_polar_samples_csv(request.body, "samples CSV");
    return json_answer(200, {{"points", points_json(marker_points_of(samples, center))}});
  }

  ApiResponse start_fit(const ApiRequest& request) {
    const json body = parse_body(request.body);
    const OmniMethod method = parse_omni_method(json_string(body, "method", "body"), "body.method");
    const json& size = json_member(body, "image", "body");
    OmniImage image;
    image.width = json_int(size, "width", "body.image", 16, 16384);
    image.height = json_int(size, "height", "body.image", 16, 16384);
    image.center_px = pixel_of(json_member(body, "center", "body"), "body.center");
    image.validate();
    // The samples the export writes, read back as `ballsight omni fit` reads them.
    const std::string csv =
        format_polar_samples_csv(polar_samples_of(points_of(body), image.center_px));
    std::vector<PolarSample> samples = parse_polar_samples_csv(csv, "body.points");

    auto job = std::make_shared<FitJob>();
    std::lock_guard lock(mutex);
    const auto running = std::count_if(fits.begin(), fits.end(), [](const auto& f) {
      std::lock_guard l(f->mutex);
      return f->state == "running";
    });
    if (static_cast<std::size_t>(running) >= kMaxRunningFits) {
      api_fail(429, "two fits are running: wait for one to finish", "fits");
    }
    job->id = next_id++;
    job->result = {{"fit", std::to_string(job->id)},
                   {"state", "running"},
                   {"method", std::string(omni_method_name(method))}};
    fits.push_back(job);
    if (fits.size() > options.max_fits) {
      const auto done = std::find_if(fits.begin(), fits.end(), [](const auto& f) {
        std::lock_guard l(f->mutex);
        return f->state != "running";
      });
      if (done != fits.end()) fits.erase(done);
    }
    join_finished_workers();
    workers.emplace_back(job, std::thread([job, method, samples = std::move(samples), image] {
                           json result;
                           std::unique_ptr<OmniGroundModel> model;
                           std::unique_ptr<GroundMap> map;
                           std::string table;
                           try {
                             OmniCalibration fit = calibrate_omni(method, samples, image);
                             result = fit_result(fit, image, samples.size());
                             result["state"] = "done";
                             table = ground_map_bytes(fit.table);
                             model = std::move(fit.model);
                             map = std::make_unique<GroundMap>(std::move(fit.table));
                           } catch (const std::exception& e) {
                             result = {{"state", "failed"}, {"error", e.what()}};
                           }
                           std::lock_guard l(job->mutex);
                           result["fit"] = job->result["fit"];
                           result["method"] = job->result["method"];
                           job->state = result["state"];
                           job->result = std::move(result);
                           job->model = std::move(model);
                           job->map = std::move(map);
                           job->table = std::move(table);
                         }));
    return json_answer(202, job->result);
  }

  std::shared_ptr<const CheckedTable> checked_table(const std::string& id) {
    std::lock_guard lock(mutex);
    return item_by_id(tables, id, "table", "no such table");
  }

  /// A table to check points against; it must be for the frame's image size.
  ApiResponse add_table(const Frame& frame, const ApiRequest& request) {
    if (!has_ground_map_magic(request.body)) {
      api_fail(415, "not a ballsight table (the IRIS int16 format holds no image size)", "body");
    }
    auto t = std::make_shared<CheckedTable>(CheckedTable{
        0, parse_ground_map(request.body, "body", cv::Size(frame.bgr.cols, frame.bgr.rows))});
    const GroundMapInfo& info = t->map.info();
    std::lock_guard lock(mutex);
    t->id = next_id++;
    tables.push_back(t);
    if (tables.size() > options.max_fits) tables.pop_front();
    return json_answer(
        201, {{"table", std::to_string(t->id)},
              {"method", info.method},
              {"width", info.width},
              {"height", info.height},
              {"center", pixel_json(info.image_center_px)},
              {"valid_radius", {{"min_px", info.min_radius_px}, {"max_px", info.max_radius_px}}}});
  }

  ApiResponse table_check(const CheckedTable& table, const ApiRequest& request) {
    const std::vector<SampleResidual> residuals =
        table_residuals(table.map, points_of(parse_body(request.body)));
    std::vector<double> errors;
    for (const SampleResidual& r : residuals)
      if (r.in_range) errors.push_back(std::abs(r.distance_error_cm));
    return json_answer(200, {{"residuals", residuals_json(residuals)},
                             {"out_of_range", residuals.size() - errors.size()},
                             {"distance_cm", summary_json(summarize_errors(errors))}});
  }

  ApiResponse fit_state(FitJob& job) {
    std::lock_guard lock(job.mutex);
    return json_answer(200, job.result);
  }

  ApiResponse table(FitJob& job, const std::string& query) {
    const std::string format = query_choice(query, "format", {"ballsight", "iris"});
    std::lock_guard lock(job.mutex);
    if (job.state != "done")
      api_fail(409, "the fit is " + job.state, "fit " + std::to_string(job.id));
    if (format == "ballsight") return bytes_answer(job.table, "application/octet-stream");
    if (!job.iris_table) {
      job.iris_table = iris_lut_bytes(iris_px2cm_from_ground_map(*job.map));
    }
    return bytes_answer(*job.iris_table, "application/octet-stream");
  }

  ApiResponse route(const ApiRequest& request, const std::vector<std::string>& parts,
                    const std::string& query) {
    return dispatch(
        request, parts,
        {{1, "files", nullptr, "GET", [&] { return files(); }},
         {1, "frames", nullptr, "POST", [&] { return add_frame(request); }},
         {2, "frames", nullptr, "GET",
          [&] { return bytes_answer(frame(parts[1])->png, "image/png"); }},
         {3, "frames", "markers", "POST", [&] { return markers(*frame(parts[1]), request); }},
         {3, "frames", "table", "POST", [&] { return add_table(*frame(parts[1]), request); }},
         {3, "tables", "residuals", "POST",
          [&] { return table_check(*checked_table(parts[1]), request); }},
         {1, "places", nullptr, "POST", [&] { return places(request); }},
         {1, "samples", nullptr, "POST", [&] { return samples_csv(request); }},
         {1, "points", nullptr, "POST", [&] { return import_csv(request, query); }},
         {1, "fits", nullptr, "POST", [&] { return start_fit(request); }},
         {2, "fits", nullptr, "GET", [&] { return fit_state(*fit(parts[1])); }},
         {3, "fits", "table", "GET", [&] { return table(*fit(parts[1]), query); }}});
  }
};

OmniCalibrationApi::OmniCalibrationApi(OmniCalibrationOptions options)
    : impl_(std::make_unique<Impl>()) {
  impl_->options = std::move(options);
}

OmniCalibrationApi::~OmniCalibrationApi() {
  for (auto& [job, thread] : impl_->workers) thread.join();
}

void OmniCalibrationApi::register_routes(ApiRoutes& routes) {
  routes.add({.prefix = kPrefix,
              .handler = [this](const ApiRequest& request) { return handle(request); },
              .runs_long = true});
}

ApiResponse OmniCalibrationApi::handle(const ApiRequest& request) {
  const RequestTarget target = split_target(request.target);
  return answer_or_error(
      [&] { return impl_->route(request, path_parts(target.path, kPrefix), target.query); });
}

}  // namespace ballsight
