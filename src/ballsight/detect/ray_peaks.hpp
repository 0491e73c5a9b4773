#pragma once
// Bright peaks along a ray of a grey image: white lines crossing it (the omni image's floor lines
// and the rings a spinning robot sees them as). A line is found as a line, however wide its image
// (near lines are many pixels wide, far ones one or two): a bar brighter than both its sides,
// its width chosen where it stands out most, never its two edges as two lines.

#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "ballsight/core/geometry.hpp"

namespace ballsight {

struct RayPeak {
  double radius_px = 0.0;  // the line's centre along the ray
  double height = 0.0;     // grey levels above the brighter of its two sides
  double width_px = 0.0;   // the bar's width where it stands out most
};

struct RayPeakOptions {
  double min_contrast = 25.0;  // grey levels a line stands above both its sides
  double max_width_px = 40.0;  // the widest line's image across the ray

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

/// The lines along the ray from `center` at image angle `theta_deg`, radii r0 to r1. At every
/// point of the ray's profile and for widths from 1 px to max_width_px, a bar of that width is
/// compared with its two sides (each half its width, 2 to 6 px): its contrast is its mean less
/// the brighter side's. A line is where the best width's contrast is at least min_contrast and
/// highest within half that width; its centre is the centroid of the bar's (and a pixel either
/// side's) grey levels above the background between its sides. Nearest first.
std::vector<RayPeak> ray_peaks(const cv::Mat1b& grey, const Vec2& center, double theta_deg,
                               double r0, double r1, const RayPeakOptions& options);

/// Plots of what was found along rays: the grey image in colour at twice its size (neighbouring
/// rings stay apart), the pixel there of image angle theta and radius r from `center`, and the
/// centre's mark.
cv::Mat ray_plot_canvas(const cv::Mat1b& grey);
cv::Point ray_plot_point(const Vec2& center, double theta_deg, double radius_px);
void mark_ray_plot_center(cv::Mat& plot, const Vec2& center);

}  // namespace ballsight
