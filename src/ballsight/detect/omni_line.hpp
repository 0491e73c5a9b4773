#pragma once
// Calibration from one straight floor line at a known distance (MinhoTeam's set-up: the robot
// stands before a field line, its omni image shows the line as a curve). The line's point
// nearest the robot lies along the line's normal; a point seen `a` degrees off the normal is at
// distance d / cos(a). Along every image direction the line is a bright bar, however wide
// (detect/ray_peaks.hpp); it is followed from its nearest point both ways, and the
// normal is the vertex of a parabola fitted to the radii around the nearest point (for a
// rotationally symmetric mirror the curve is symmetric about it). A point much fainter than its
// neighbours, or one beside a stretch where the line is hidden, is the line partly hidden (at a
// strut's edge), its centre biased: left out; so is the last point before the line is lost.

#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "ballsight/core/geometry.hpp"
#include "ballsight/detect/ray_peaks.hpp"

namespace ballsight {

struct LineSearchOptions {
  double toward_deg = 90.0;             // image direction the line lies in, roughly
  double window_deg = 30.0;             // its nearest point is searched within +-this of toward_deg
  double max_off_normal_deg = 70.0;     // farther off the normal the line runs out of the image
  double step_deg = 1.0;                // between directions
  double min_radius_px = 20.0;          // the search starts here (inside: the robot itself)
  std::optional<double> max_radius_px;  // default: the largest circle inside the image
  double tolerance_px = 3.0;            // how far a direction's peak may lie from the line's course
  int max_gap = 4;  // directions in a row without the line end it (a strut hides it)
  RayPeakOptions peaks;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

struct LinePoint {
  double theta_deg = 0.0;       // image angle (core/conventions.hpp), [0, 360)
  double radius_px = 0.0;       // where the line crosses it
  double off_normal_deg = 0.0;  // from the line's normal: the point is d / cos of it away
  double contrast = 0.0;        // grey levels above the local background
};

struct LineSearch {
  double normal_deg = 0.0;         // image angle of the line's normal
  double nearest_radius_px = 0.0;  // the parabola's vertex: the line's image radius at d
  std::vector<LinePoint> points;   // by image angle
};

/// Finds one straight line's image in a grey image around `center`. Throws InputError naming
/// the image when no line is seen near `toward_deg` or it is too short to find its normal.
LineSearch find_omni_line(const cv::Mat1b& grey, const Vec2& center,
                          const LineSearchOptions& options);

/// The image with each found line point (green), the normal (blue) and the centre.
cv::Mat plot_omni_line(const cv::Mat1b& grey, const Vec2& center, const LineSearch& search);

}  // namespace ballsight
