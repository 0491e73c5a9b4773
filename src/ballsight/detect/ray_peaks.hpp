#pragma once
// Bright peaks along a ray of a grey image: white lines crossing it (the omni image's floor lines
// and the rings a spinning robot sees them as).

#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "ballsight/core/geometry.hpp"

namespace ballsight {

struct RayPeak {
  double radius_px = 0.0;  // the peak's centre along the ray
  double height = 0.0;     // grey levels above the local background
};

struct RayPeakOptions {
  double min_contrast = 25.0;  // grey levels a peak stands above its background
  double background_px = 5.0;  // half-width of the top-hat's window (lines are narrower)

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

struct RaySpan {
  double r0 = 0.0, r1 = 0.0;  // radii searched along every ray
};

/// Throws InputError naming the first invalid radius: min_radius_px >= 0, max_radius_px (when
/// given) above min_radius_px + 2.
void validate_ray_radii(double min_radius_px, std::optional<double> max_radius_px);

/// The radii searched from `center` (radii valid): min_radius_px out to max_radius_px, or to the
/// largest circle inside the image. Throws InputError naming what is wrong: an empty image, a
/// centre outside it, or no room between the radii.
RaySpan ray_span(const cv::Mat1b& grey, const Vec2& center, double min_radius_px,
                 std::optional<double> max_radius_px);

/// The bright peaks along the ray from `center` at image angle `theta_deg`, radii r0 to r1: the
/// white top-hat of the ray's profile (the profile minus its opening) at least min_contrast, each
/// peak's centre the centroid of the top-hat above half its height. Nearest first.
std::vector<RayPeak> ray_peaks(const cv::Mat1b& grey, const Vec2& center, double theta_deg,
                               double r0, double r1, const RayPeakOptions& options);

/// Plots of what was found along rays: the grey image in colour at twice its size (neighbouring
/// rings stay apart), the pixel there of image angle theta and radius r from `center`, and the
/// centre's mark.
cv::Mat ray_plot_canvas(const cv::Mat1b& grey);
cv::Point ray_plot_point(const Vec2& center, double theta_deg, double radius_px);
void mark_ray_plot_center(cv::Mat& plot, const Vec2& center);

}  // namespace ballsight
