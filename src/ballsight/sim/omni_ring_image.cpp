#include "ballsight/sim/omni_ring_image.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/conventions.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/sim/image_effects.hpp"
#include "ballsight/sim/seeding.hpp"

namespace ballsight::sim {

namespace {

constexpr int kSamplesPerAxis = 4;  // per pixel and axis
constexpr double kBodyGrey = 25.0;
constexpr double kStrutGrey = 18.0;
constexpr double kAboveHorizonGrey = 150.0;

// A lattice value in [-1, 1] for cell (x, y) of stream `seed`.
double lattice(std::int64_t x, std::int64_t y, std::uint64_t seed) {
  const std::uint64_t h = derive_seed(seed ^ static_cast<std::uint64_t>(x) * 0x9E3779B1ULL,
                                      static_cast<std::uint64_t>(y));
  return static_cast<double>(h >> 11) * 0x1.0p-52 - 1.0;
}

// Smooth value noise in [-1, 1] at p (cells of one unit).
double value_noise(const Vec2& p, std::uint64_t seed) {
  const double fx = std::floor(p.x()), fy = std::floor(p.y());
  const auto x = static_cast<std::int64_t>(fx), y = static_cast<std::int64_t>(fy);
  const auto smooth = [](double t) { return t * t * (3.0 - 2.0 * t); };
  const double tx = smooth(p.x() - fx), ty = smooth(p.y() - fy);
  const double top = (1.0 - tx) * lattice(x, y, seed) + tx * lattice(x + 1, y, seed);
  const double bottom = (1.0 - tx) * lattice(x, y + 1, seed) + tx * lattice(x + 1, y + 1, seed);
  return (1.0 - ty) * top + ty * bottom;
}

}  // namespace

void RingImageSpec::validate() const {
  rig.validate();
  require(std::isfinite(robot_body_radius_m) && robot_body_radius_m >= 0.0, "robot_body_radius_m",
          "expected a number >= 0");
  require(!distances_m.empty(), "distances_m", "expected at least one line");
  require(line_widths_m.size() == 1 || line_widths_m.size() == distances_m.size(), "line_widths_m",
          "expected one width, or one per line");
  for (std::size_t k = 0; k < distances_m.size(); ++k) {
    const double w = line_width_m(k);
    require(std::isfinite(w) && w > 0.0, "line_widths_m", "expected positive widths");
    require(std::isfinite(distances_m[k]) && distances_m[k] - 0.5 * w > robot_body_radius_m &&
                (k == 0 || distances_m[k] > distances_m[k - 1]),
            "distances_m", "expected increasing distances, each line beyond the robot's body");
  }
  require(std::all_of(strut_deg.begin(), strut_deg.end(),
                      [](double theta) { return std::isfinite(theta); }),
          "strut_deg", "expected finite image angles");
  require(std::isfinite(strut_width_px) && strut_width_px >= 1.0 && strut_width_px <= 100.0,
          "strut_width_px", "expected 1 to 100");
  require(carpet_grey >= 0.0 && carpet_grey <= 255.0 && line_grey >= 0.0 && line_grey <= 255.0,
          "carpet_grey, line_grey", "expected 0 to 255");
  require(std::isfinite(carpet_texture) && carpet_texture >= 0.0, "carpet_texture",
          "expected a number >= 0");
  require(std::isfinite(carpet_scale_m) && carpet_scale_m > 0.0, "carpet_scale_m",
          "expected a positive number");
  require(std::isfinite(noise_sigma) && noise_sigma >= 0.0, "noise_sigma",
          "expected a number >= 0");
}

RingImage::RingImage(const RingImageSpec& spec) : spec_(spec), rig_((spec.validate(), spec.rig)) {
  const auto floor_grey = [&](const Vec2& p) {
    const double d = p.norm();
    if (d < spec_.robot_body_radius_m) return kBodyGrey;
    for (std::size_t k = 0; k < spec_.distances_m.size(); ++k) {
      if (std::abs(d - spec_.distances_m[k]) <= 0.5 * spec_.line_width_m(k)) return spec_.line_grey;
    }
    const Vec2 q = p / spec_.carpet_scale_m;
    return spec_.carpet_grey + spec_.carpet_texture * (0.65 * value_noise(q, spec_.seed) +
                                                       0.35 * value_noise(4.0 * q, spec_.seed + 1));
  };
  const OmniRigParams& r = spec_.rig;
  const Vec2 pp = rig_.principal_point();
  cv::Mat bgr(r.height, r.width, CV_8UC3);
  for (int y = 0; y < r.height; ++y) {
    for (int x = 0; x < r.width; ++x) {
      double sum = 0.0;
      for (int sy = 0; sy < kSamplesPerAxis; ++sy) {
        for (int sx = 0; sx < kSamplesPerAxis; ++sx) {
          const Vec2 pixel(x + (sx + 0.5) / kSamplesPerAxis - 0.5,
                           y + (sy + 0.5) / kSamplesPerAxis - 0.5);
          const std::optional<Vec2> floor = rig_.ground_from_pixel(pixel);
          sum += floor                                      ? floor_grey(*floor)
                 : (pixel - pp).norm() > r.mirror_radius_px ? 0.0
                                                            : kAboveHorizonGrey;
        }
      }
      const auto v = cv::saturate_cast<uchar>(sum / (kSamplesPerAxis * kSamplesPerAxis));
      bgr.at<cv::Vec3b>(y, x) = {v, v, v};
    }
  }
  for (const double theta : spec_.strut_deg) {
    const Vec2 end = pixel_from_image_polar({theta, r.mirror_radius_px}, pp);
    constexpr int shift = 4;
    const auto fixed = [](double v) { return static_cast<int>(std::lround(v * (1 << shift))); };
    cv::line(bgr, {fixed(pp.x()), fixed(pp.y())}, {fixed(end.x()), fixed(end.y())},
             cv::Scalar::all(kStrutGrey), static_cast<int>(std::lround(spec_.strut_width_px)),
             cv::LINE_AA, shift);
  }
  ImageEffects effects;
  effects.noise_sigma = spec_.noise_sigma;
  effects.quantile_noise = true;
  apply_image_effects(bgr, effects, spec_.seed);
  cv::cvtColor(bgr, grey_, cv::COLOR_BGR2GRAY);
}

std::optional<double> RingImage::true_radius_px(double theta_deg, std::size_t k) const {
  const double d = spec_.distances_m.at(k);
  const Vec2 c = center();
  const auto distance_at = [&](double radius) -> std::optional<double> {
    const std::optional<Vec2> floor =
        rig_.ground_from_pixel(pixel_from_image_polar({theta_deg, radius}, c));
    return floor ? std::optional<double>(floor->norm()) : std::nullopt;
  };
  double lo = 1.0;
  double hi = lo;
  for (;; hi += 1.0) {  // the first whole pixel beyond the line
    if (hi > spec_.rig.mirror_radius_px) return std::nullopt;
    const std::optional<double> at = distance_at(hi);
    if (!at) return std::nullopt;
    if (*at >= d) break;
    lo = hi;
  }
  for (int i = 0; i < 40; ++i) {
    const double mid = 0.5 * (lo + hi);
    const std::optional<double> at = distance_at(mid);
    (at && *at >= d ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

bool RingImage::strut_hides(double theta_deg, double radius_px) const {
  for (const double strut : spec_.strut_deg) {
    const double gap = rad_from_deg(wrap_deg_180(theta_deg - strut));
    if (std::cos(gap) > 0.0 &&
        std::abs(std::sin(gap)) * radius_px <= 0.5 * spec_.strut_width_px + 1.5)
      return true;
  }
  return false;
}

}  // namespace ballsight::sim
