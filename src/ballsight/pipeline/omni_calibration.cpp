#include "ballsight/pipeline/omni_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "ballsight/calib/model_ground_map.hpp"
#include "ballsight/core/angle.hpp"
#include "ballsight/core/conventions.hpp"

namespace ballsight {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

std::vector<PolarSample> polar_samples_of(std::span<const MarkerPoint> points,
                                          const Vec2& image_center) {
  std::vector<PolarSample> samples;
  samples.reserve(points.size());
  for (const MarkerPoint& p : points) {
    const Polar polar = image_polar_from_pixel(p.pixel, image_center);
    PolarSample s{polar.theta_deg, polar.radius, p.distance_cm, std::nullopt};
    if (p.bearing_deg) {
      s.bearing_deg = wrap_deg_360(image_theta_deg_from_robot_bearing_deg(*p.bearing_deg));
    }
    samples.push_back(s);
  }
  return samples;
}

std::vector<MarkerPoint> marker_points_of(std::span<const PolarSample> samples,
                                          const Vec2& image_center) {
  std::vector<MarkerPoint> points;
  points.reserve(samples.size());
  for (const PolarSample& s : samples) {
    MarkerPoint p{pixel_from_image_polar({s.theta_deg, s.radius_px}, image_center), s.distance_cm,
                  std::nullopt};
    if (s.bearing_deg) {
      p.bearing_deg = wrap_deg_360(robot_bearing_deg_from_image_theta_deg(*s.bearing_deg));
    }
    points.push_back(p);
  }
  return points;
}

OmniCalibration calibrate_omni(OmniMethod method, std::span<const PolarSample> samples,
                               const OmniImage& image, const OmniFitOptions& options) {
  std::unique_ptr<OmniGroundModel> model = fit_omni_model(method, samples, image, options);
  GroundMap table = ground_map_from_model(*model);
  std::vector<SampleResidual> residuals;
  residuals.reserve(samples.size());
  for (const PolarSample& s : samples) {
    const GroundPrediction g = model->predict(s.theta_deg, s.radius_px);
    SampleResidual r{g.distance_cm, g.distance_cm - s.distance_cm, std::nullopt, g.in_range};
    if (s.bearing_deg && g.bearing_deg) {
      r.bearing_error_deg = wrap_deg_180(*g.bearing_deg - *s.bearing_deg);
    }
    residuals.push_back(r);
  }
  GroundErrors errors = sample_errors(*model, samples);
  return {std::move(model), std::move(table), errors, std::move(residuals)};
}

std::vector<SampleResidual> table_residuals(const GroundMap& table,
                                            std::span<const MarkerPoint> points) {
  std::vector<SampleResidual> residuals;
  residuals.reserve(points.size());
  for (const MarkerPoint& p : points) {
    SampleResidual r{kNaN, kNaN, std::nullopt, false};
    if (const std::optional<Vec2> floor = table.robot_point_cm(p.pixel)) {
      r.predicted_distance_cm = floor->norm();
      r.distance_error_cm = r.predicted_distance_cm - p.distance_cm;
      r.in_range = true;
      if (p.bearing_deg) {
        r.bearing_error_deg =
            wrap_deg_180(deg_from_rad(std::atan2(floor->y(), floor->x())) - *p.bearing_deg);
      }
    }
    residuals.push_back(r);
  }
  return residuals;
}

std::vector<RadialCurve> radial_curves(const OmniGroundModel& model, int directions, int points) {
  const RadiusRange range = model.domain().valid_radius;
  std::vector<RadialCurve> curves;
  for (int d = 0; d < directions; ++d) {
    RadialCurve curve;
    curve.theta_deg = 360.0 * d / directions;
    for (int i = 0; i < points; ++i) {
      const double r = range.min_px + (range.max_px - range.min_px) * i / std::max(1, points - 1);
      const double distance = model.predict(curve.theta_deg, r).distance_cm;
      curve.radius_px.push_back(r);
      curve.distance_cm.push_back(std::isfinite(distance) ? distance : kNaN);
    }
    curves.push_back(std::move(curve));
  }
  return curves;
}

std::vector<MarkerPoint> suggest_layout_places(std::span<const Vec2> pixels,
                                               const Vec2& image_center, const MarkerLayout& layout,
                                               const OmniGroundModel* model) {
  layout.validate();
  const int rays = layout.rays();
  const auto ring_distance_cm = [&](int ring) {
    return 100.0 * layout.ring_distance_m(std::clamp(ring, 0, layout.rings() - 1));
  };
  std::vector<MarkerPoint> places;
  std::map<int, std::vector<std::pair<double, std::size_t>>> by_ray;  // ray -> (radius, index)
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    const Polar polar = image_polar_from_pixel(pixels[i], image_center);
    const double bearing = wrap_deg_360(robot_bearing_deg_from_image_theta_deg(polar.theta_deg));
    const int ray = static_cast<int>(std::lround(bearing / layout.bearing_step_deg)) % rays;
    MarkerPoint p{pixels[i], ring_distance_cm(0), ray * layout.bearing_step_deg};
    if (model) {
      const double d = model->predict(polar.theta_deg, polar.radius).distance_cm;
      if (std::isfinite(d)) {
        const double ring = (0.01 * d - layout.min_distance_m) / layout.distance_step_m;
        p.distance_cm = ring_distance_cm(static_cast<int>(std::lround(ring)));
      }
    } else {
      by_ray[ray].push_back({polar.radius, i});
    }
    places.push_back(p);
  }
  for (auto& [ray, members] : by_ray) {
    std::sort(members.begin(), members.end());
    for (std::size_t k = 0; k < members.size(); ++k) {
      places[members[k].second].distance_cm = ring_distance_cm(static_cast<int>(k));
    }
  }
  return places;
}

}  // namespace ballsight
