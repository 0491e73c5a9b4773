#pragma once
// Calibration from one spin (the cnc-msl robots' carpet calibration): a robot turning on the spot
// over white floor lines at known distances accumulates one bright ring per line in its omni
// image. Along every image direction the lines are found as lines (detect/ray_peaks.hpp: a bar
// brighter than both its sides, however wide). The rings are then told apart where the lines of
// all directions gather, with the rings' centre off the given one found first (a mirror off the
// image centre, a tilted camera), and chosen in the given distances' order: of the radii where
// lines gather, the set with the most support whose spacing a mirror can give (the radius grows
// with the distance, per metre no faster than 1.25 times its growth between the two rings
// before). Each ring is then followed around the image as a smooth closed curve (a short Fourier
// series in the image angle, refitted to what it finds, with the neighbours' departures from it):
// in a direction a ring is its one line near the curve, or missing there (hidden: a strut, or a
// line much fainter than its neighbours', a ring partly hidden at a strut's edge; ambiguous: two
// lines), never the next ring's line. Directions where every ring is missing are reported as
// blocked spans (the robot's struts).

#include <array>
#include <opencv2/core.hpp>
#include <optional>
#include <span>
#include <vector>

#include "ballsight/core/geometry.hpp"
#include "ballsight/detect/ray_peaks.hpp"

namespace ballsight {

struct RingSearchOptions {
  std::vector<double>
      distances_m;              // the lines' distances from the robot, increasing: one ring each
  int directions = 180;         // evenly spread image directions when none are given
  double min_radius_px = 20.0;  // the search starts here (inside: the robot itself)
  std::optional<double> max_radius_px;  // default: the largest circle inside the image
  double min_contrast = 25.0;           // grey levels a ring stands above both its sides
  double max_width_px = 40.0;           // the widest ring's image across a direction
  double tolerance_px = 4.0;            // how far a ring's line may lie from where the ring runs
  double min_support = 0.3;             // fraction of directions a ring must be seen in
  double max_decentring_px = 12.0;      // how far the rings' centre may lie from the given one

  RayPeakOptions peaks() const {
    return {.min_contrast = min_contrast, .max_width_px = max_width_px};
  }

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

enum class RingMiss { kNone, kHidden, kAmbiguous };

struct RingDirection {
  double theta_deg = 0.0;                        // image angle (core/conventions.hpp)
  std::vector<std::optional<double>> radius_px;  // per ring; nullopt when missing
  std::vector<RingMiss> miss;                    // per ring: why it is missing
};

// One ring as a closed curve: radius = a0 + a1 cos t + b1 sin t + a2 cos 2t + b2 sin 2t at image
// angle t.
struct RingCurve {
  std::array<double, 5> coefficients{};  // a0, a1, b1, a2, b2
  double median_radius_px = 0.0;         // of the directions it was found in
  double found_fraction = 0.0;           // of the directions searched
  double residual_px = 0.0;              // median |found radius - the curve|

  double radius_at(double theta_deg) const;
};

// Directions in a row (by image angle) where every ring is missing.
struct BlockedSpan {
  double from_deg = 0.0, to_deg = 0.0;  // image angles, counter-clockwise from -> to
  std::size_t directions = 0;
};

struct RingSearch {
  std::vector<RingCurve> rings;
  std::vector<RingDirection> directions;
  std::vector<BlockedSpan> blocked;
  Vec2 decentring_px = Vec2::Zero();  // the rings' centre less the given one, as first found
  std::size_t hidden = 0;
  std::size_t ambiguous = 0;
};

/// Finds the rings in a grey image around `center` along `directions_deg` (image angles, finite,
/// at most 3600), or along `options.directions` evenly spread ones when empty. Throws InputError
/// naming the image when fewer rings than distances are seen in enough directions with a spacing
/// a mirror gives.
RingSearch find_omni_rings(const cv::Mat1b& grey, const Vec2& center,
                           const RingSearchOptions& options,
                           std::span<const double> directions_deg = {});

/// The image with each found ring point (green), each missing one (red: hidden, orange:
/// ambiguous, drawn on the ring's curve) and the centre.
cv::Mat plot_omni_rings(const cv::Mat1b& grey, const Vec2& center, const RingSearch& search);

}  // namespace ballsight
