#include "ballsight/eval/plot_inputs.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <string>

#include "ballsight/core/text_format.hpp"

namespace ballsight {

namespace {

FieldRect field_rect_of(const sim::GroundRect& r) {
  return {Vec2(r.x_min, r.y_min), Vec2(r.x_max, r.y_max)};
}

cv::Scalar scalar_of(const cv::Vec3b& bgr) {
  return {static_cast<double>(bgr[0]), static_cast<double>(bgr[1]), static_cast<double>(bgr[2])};
}

// The largest written distance of any direction: it scales the distance axis and the heat map.
double largest_written_cm(const InspectedLut& lut, const LutInspection& inspection) {
  double largest = 0.0;
  for (int theta = 0; theta < RadialTable::kDirections; ++theta) {
    const RayFindings& f = inspection.rays[static_cast<std::size_t>(theta)];
    if (!f.first_written_px) continue;
    const std::span<const float> ray = lut.rays.ray(theta);
    const auto first = static_cast<std::size_t>(lut.rays.bin_at(*f.first_written_px));
    const auto last = static_cast<std::size_t>(lut.rays.bin_at(*f.last_written_px));
    for (std::size_t i = first; i <= last; ++i) {
      if (std::isfinite(ray[i])) largest = std::max<double>(largest, ray[i]);
    }
  }
  return largest;
}

std::string lut_summary(const LutInspection& in) {
  std::string text =
      "first written " +
      (in.first_written_min_px ? fixed(*in.first_written_min_px, 1) + " px" : std::string("never"));
  if (in.monotonic_until_px) {
    text += "   monotonic until " + fixed(*in.monotonic_until_px, 1) + " px (" +
            std::to_string(in.non_monotonic_directions) + " of " + std::to_string(in.rays.size()) +
            " directions drop)";
  }
  for (const RadiusSpread& s : in.spread) {
    if (s.radius_px == 200.0) text += "   spread at 200 px " + fixed(s.spread_cm(), 0) + " cm";
  }
  return text + "   holes " + std::to_string(in.holes);
}

// The ray in `theta_deg` over its written range, or nullopt when it was never written.
std::optional<LutProfile> lut_profile(const InspectedLut& lut, const LutInspection& inspection,
                                      const std::vector<double>& radius_px, int theta_deg) {
  const RayFindings& f = inspection.rays[static_cast<std::size_t>(theta_deg)];
  if (!f.first_written_px) return std::nullopt;
  const std::span<const float> ray = lut.rays.ray(theta_deg);
  LutProfile profile;
  profile.distance_cm.assign(radius_px.size(), std::nan(""));
  for (std::size_t i = 0; i < radius_px.size(); ++i) {
    if (radius_px[i] >= *f.first_written_px && radius_px[i] <= *f.last_written_px)
      profile.distance_cm[i] = ray[i];
  }
  if (f.drop_px) {
    profile.drop_px = f.drop_px;
    profile.distance_at_drop_cm = ray[static_cast<std::size_t>(lut.rays.bin_at(*f.drop_px))];
  }
  return profile;
}

// The omni experiment's methods, one colour each.
const std::map<std::string, cv::Scalar> kMethodColours = {{"poly", {40, 40, 220}},
                                                          {"paper-mlp", {0, 150, 240}},
                                                          {"ballsight", {200, 110, 0}},
                                                          {"ballsight-auto", {60, 170, 40}},
                                                          {"oracle", {60, 60, 60}}};

}  // namespace

CourtFloor court_floor(const sim::TennisCourtSpec& court) {
  CourtFloor floor;
  floor.surround = field_rect_of(court.surround_rect());
  floor.court = field_rect_of(court.court_rect());
  for (const sim::GroundRect& line : court.line_rects()) floor.lines.push_back(field_rect_of(line));
  floor.surround_bgr = scalar_of(court.surround_bgr);
  floor.court_bgr = scalar_of(court.court_bgr);
  floor.line_bgr = scalar_of(court.line_bgr);
  if (court.net.enabled)
    floor.net_posts_y_m = court.doubles_width_m / 2.0 + court.net.post_outside_doubles_m;
  floor.net_bgr = scalar_of(court.net.mesh_bgr);
  return floor;
}

LoopMapInput loop_map_input(const LoopTruth& truth) {
  LoopMapInput run;
  run.robot_start = truth.robot_start;
  std::map<int, double> collected_at;  // the first tick that reports a ball collected
  for (const TruthTick& t : truth.ticks) {
    run.path_m.push_back(t.world.robot.position);
    if (t.published.waypoints_m.size() > 1)
      run.routes.push_back({t.world.time_s, t.published.waypoints_m});
    for (const int id : t.world.collected) collected_at.emplace(id, t.world.time_s);
  }
  for (const SceneBall& b : truth.balls) {
    const auto it = collected_at.find(b.id);
    run.balls.push_back(
        {b.position_m, it == collected_at.end() ? std::nullopt : std::optional(it->second)});
  }
  run.duration_s = truth.ticks.empty() ? 0.0 : truth.ticks.back().world.time_s;
  return run;
}

LutFigureInput lut_figure_input(const InspectedLut& lut, const LutInspection& inspection) {
  const RadialTable& rays = lut.rays;
  LutFigureInput figure;
  figure.title = lut.source + "  (" + inspection.format + ")";
  figure.summary = lut_summary(inspection);
  for (int bin = 0; bin < rays.bins; ++bin) figure.radius_px.push_back(rays.radius_px(bin));
  figure.radius_end_px = rays.radius_px(rays.bins);
  for (std::size_t k = 0; k < kLutFigureDirectionsDeg.size(); ++k) {
    figure.profiles[k] = lut_profile(lut, inspection, figure.radius_px, kLutFigureDirectionsDeg[k]);
  }
  figure.largest_distance_cm = largest_written_cm(lut, inspection);
  if (inspection.monotonic_until_px) {
    const std::string where = fixed(*inspection.monotonic_until_px, 1) + " px";
    figure.monotonic_until_px = inspection.monotonic_until_px;
    figure.monotonic_label = inspection.non_monotonic_directions == 0
                                 ? "monotonic over the written range (to " + where + ")"
                                 : "monotonic until " + where + " (theta " +
                                       std::to_string(inspection.monotonic_until_theta_deg) + ")";
  }
  figure.distance_image_cm = lut.distance_image_cm;
  figure.image_center_px = lut.image_center_px;
  return figure;
}

std::vector<TrueBallMark> true_ball_marks(const std::vector<TruthBall>& truth) {
  std::vector<TrueBallMark> marks;
  for (const TruthBall& t : truth) marks.push_back({t.position_m, t.seen});
  return marks;
}

std::vector<MistakeMark> mistake_marks(const std::vector<BallMistake>& mistakes) {
  std::vector<MistakeMark> marks;
  for (const BallMistake& m : mistakes) {
    marks.push_back(
        {m.position_m, static_cast<char>(std::toupper(mistake_kind_name(m.kind).front()))});
  }
  return marks;
}

std::vector<EstimateLayer> estimate_layers(const OmniExperimentResult& result) {
  std::vector<EstimateLayer> layers;
  for (const auto& [name, method] : result.methods) {
    if (method.by_distance.empty()) continue;  // not calibrated
    EstimateLayer& layer = layers.emplace_back();
    layer.label = name;
    layer.colour = kMethodColours.at(name);
    for (const int distance : result.options.distances_cm)
      layer.estimates_cm.push_back(method.by_distance.at(distance).estimates_cm);
  }
  return layers;
}

}  // namespace ballsight
