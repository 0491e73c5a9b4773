#include "ballsight/service/run_setup.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "ballsight/camera/image_file.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

using nlohmann::json;

constexpr const char* kSite = "replay/site.yml";
constexpr const char* kSetup = "replay/setup.json";

std::string empty_court_name(std::size_t camera) {
  std::string name = "replay/empty_court_";
  name += std::to_string(camera);
  return name + ".png";
}

json camera_json(const FieldCamera& camera) {
  const PinholeParams& p = camera.camera.params();
  const Mat3& r = camera.camera_from_field.rotation;
  const Vec3& t = camera.camera_from_field.translation;
  json rotation = json::array();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) rotation.push_back(r(i, j));
  return {{"width", p.width},
          {"height", p.height},
          {"fx", p.fx},
          {"fy", p.fy},
          {"cx", p.cx},
          {"cy", p.cy},
          {"distortion", p.distortion},
          {"rotation", rotation},
          {"translation", {t.x(), t.y(), t.z()}}};
}

FieldCamera parse_camera(const json& j) {
  PinholeParams p;
  p.width = j.at("width").get<int>();
  p.height = j.at("height").get<int>();
  p.fx = j.at("fx").get<double>();
  p.fy = j.at("fy").get<double>();
  p.cx = j.at("cx").get<double>();
  p.cy = j.at("cy").get<double>();
  p.distortion = j.at("distortion").get<Distortion::Coefficients>();
  p.validate();
  FieldCamera camera{PinholeCamera(p), {}};
  const std::vector<double> r = j.at("rotation").get<std::vector<double>>();
  const std::vector<double> t = j.at("translation").get<std::vector<double>>();
  require(r.size() == 9 && t.size() == 3, "camera", "needs 9 rotation and 3 translation values");
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) camera.camera_from_field.rotation(i, k) = r[3 * i + k];
  camera.camera_from_field.translation = Vec3(t[0], t[1], t[2]);
  return camera;
}

json planner_json(const PlannerOptions& o) {
  return {{"kind", planner_name(o.kind)},
          {"cost", o.cost == CostKind::time ? "time" : "distance"},
          {"effort", o.effort},
          {"seed", o.seed},
          {"sweep", o.sweep},
          {"priority_per_cm", o.priority.per_cm},
          {"priority_per_deg", o.priority.per_deg},
          {"target_switch_margin_s", o.target_switch_margin_s}};
}

PlannerOptions parse_planner(const json& j) {
  PlannerOptions o;
  const std::string kind = j.at("kind").get<std::string>();
  const std::optional<PlannerKind> known = planner_from_name(kind);
  require(known.has_value(), "planner", "unknown kind '" + kind + "'");
  o.kind = *known;
  o.cost = j.at("cost").get<std::string>() == "time" ? CostKind::time : CostKind::distance;
  o.effort = j.at("effort").get<double>();
  o.seed = j.at("seed").get<std::uint64_t>();
  o.sweep = j.at("sweep").get<bool>();
  o.priority.per_cm = j.at("priority_per_cm").get<double>();
  o.priority.per_deg = j.at("priority_per_deg").get<double>();
  o.target_switch_margin_s = j.at("target_switch_margin_s").get<double>();
  o.validate();
  return o;
}

}  // namespace

std::vector<mcap::Attachment> run_setup_attachments(const RunSetup& setup, std::int64_t time_ns) {
  const auto t = static_cast<std::uint64_t>(time_ns);
  json cameras = json::array();
  for (const FieldCamera& camera : setup.pipeline.cameras) cameras.push_back(camera_json(camera));
  const json description{
      {"method", setup.pipeline.method == CourtMethod::seed ? "seed" : "ballsight"},
      {"cameras", cameras},
      {"empty_court", !setup.pipeline.empty_court.empty()},
      {"planner", planner_json(setup.planner)}};
  // Its paths absolute: read back, they are not taken for paths beside the recording.
  Site site = setup.site;
  for (SiteCamera& camera : site.cameras) {
    if (!camera.calibration_file.empty())
      camera.calibration_file = std::filesystem::absolute(camera.calibration_file);
    if (!camera.source.path.empty())
      camera.source.path = std::filesystem::absolute(camera.source.path);
  }
  std::vector<mcap::Attachment> out{{t, t, kSite, "application/yaml", {site_file_text(site)}},
                                    {t, t, kSetup, "application/json", {description.dump(2)}}};
  for (std::size_t k = 0; k < setup.pipeline.empty_court.size(); ++k) {
    std::vector<std::uint8_t> png;
    cv::imencode(".png", setup.pipeline.empty_court[k], png);
    out.push_back({t, t, empty_court_name(k), "image/png", {std::string(png.begin(), png.end())}});
  }
  return out;
}

RunSetup read_run_setup(const std::vector<mcap::Attachment>& attachments,
                        const std::string& where) {
  const auto find = [&](const std::string& name) -> const std::string& {
    const auto it = std::find_if(attachments.begin(), attachments.end(),
                                 [&](const mcap::Attachment& a) { return a.name == name; });
    require(it != attachments.end(), where,
            "has no attachment " + name + ": it was not recorded by this version of ballsight");
    return it->data.bytes;
  };
  RunSetup setup;
  setup.site = parse_site(find(kSite), where + ": " + kSite);
  const std::string context = where + ": " + kSetup;
  try {
    const json description = json::parse(find(kSetup));
    const std::string method = description.at("method").get<std::string>();
    require(method == "seed" || method == "ballsight", "method", "unknown '" + method + "'");
    setup.pipeline.method = method == "seed" ? CourtMethod::seed : CourtMethod::ballsight;
    for (const json& camera : description.at("cameras"))
      setup.pipeline.cameras.push_back(parse_camera(camera));
    setup.planner = parse_planner(description.at("planner"));
    if (description.at("empty_court").get<bool>()) {
      for (std::size_t k = 0; k < setup.pipeline.cameras.size(); ++k) {
        const std::string& png = find(empty_court_name(k));
        const PinholeParams& p = setup.pipeline.cameras[k].camera.params();
        setup.pipeline.empty_court.push_back(
            decode_image_bgr(png, empty_court_name(k), cv::Size(p.width, p.height)));
      }
    }
  } catch (const InputError& e) {
    throw InputError(context + ": " + e.what());
  } catch (const json::exception& e) {
    throw InputError(context + ": " + e.what());
  }
  require(setup.pipeline.cameras.size() == setup.site.cameras.size(), context,
          "has " + std::to_string(setup.pipeline.cameras.size()) + " cameras, the site " +
              std::to_string(setup.site.cameras.size()));
  return setup;
}

}  // namespace ballsight
