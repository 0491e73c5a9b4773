#pragma once
// Calibration from one spin (the cnc-msl robots' carpet calibration): a robot turning on the spot
// over white floor lines at known distances accumulates one bright ring per line in its omni
// image. Along every image direction the rings are found as brightness peaks over the local
// background (a white top-hat of the ray's profile, sub-pixel centre of each peak), the rings
// are told apart by where the peaks of all directions gather, and each ring is followed around
// the image. A direction's ring is rejected when no peak lies near where the ring runs there
// (hidden: the robot's own struts, or a peak much lower than its neighbours': a ring partly
// hidden at a strut's edge) or more than one does (ambiguous).

#include <opencv2/core.hpp>
#include <optional>
#include <span>
#include <vector>

#include "ballsight/core/geometry.hpp"
#include "ballsight/detect/ray_peaks.hpp"

namespace ballsight {

struct RingSearchOptions {
  std::size_t rings = 1;        // how many rings, from the centre out (one per line distance)
  int directions = 180;         // evenly spread image directions when none are given
  double min_radius_px = 20.0;  // the search starts here (inside: the robot itself)
  std::optional<double> max_radius_px;  // default: the largest circle inside the image
  double min_contrast = 25.0;           // grey levels a ring stands above its background
  double background_px = 5.0;           // half-width of the top-hat's window (rings are narrower)
  double tolerance_px = 4.0;            // how far a ring's peak may lie from where the ring runs
  double min_support = 0.3;             // fraction of directions a ring must be seen in

  RayPeakOptions peaks() const {
    return {.min_contrast = min_contrast, .background_px = background_px};
  }

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

enum class RingMiss { kNone, kHidden, kAmbiguous };

struct RingDirection {
  double theta_deg = 0.0;                        // image angle (core/conventions.hpp)
  std::vector<std::optional<double>> radius_px;  // per ring; nullopt when rejected
  std::vector<RingMiss> miss;                    // per ring: why it was rejected
};

struct RingSearch {
  std::vector<double> ring_radius_px;  // each ring's median radius over the directions
  std::vector<RingDirection> directions;
  std::size_t hidden = 0;
  std::size_t ambiguous = 0;
};

/// Finds the rings in a grey image around `center` along `directions_deg` (image angles), or
/// along `options.directions` evenly spread ones when empty. Throws InputError naming the image
/// when fewer rings than asked are seen in enough directions.
RingSearch find_omni_rings(const cv::Mat1b& grey, const Vec2& center,
                           const RingSearchOptions& options,
                           std::span<const double> directions_deg = {});

/// The image with each found ring point (green), each rejected one (red: hidden, orange:
/// ambiguous, drawn at the ring's median radius) and the centre.
cv::Mat plot_omni_rings(const cv::Mat1b& grey, const Vec2& center, const RingSearch& search);

}  // namespace ballsight
