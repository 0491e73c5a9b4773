#pragma once
// The figure of `ballsight omni inspect --plot`: ground distance against pixel radius for
// several directions with the monotonic limit marked, and a heat map of the ground distance
// over the image with a scale bar. eval/plot_inputs.hpp reads a table's inspection
// (calib/lut_inspect.hpp) into LutFigureInput.

#include <array>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ballsight/core/geometry.hpp"

namespace ballsight {

/// The directions the figure plots (image angle, counter-clockwise from the image's right), one
/// colour each.
inline constexpr std::array<int, 8> kLutFigureDirectionsDeg{0, 45, 90, 135, 180, 225, 270, 315};

/// One plotted direction of a table.
struct LutProfile {
  std::vector<double> distance_cm;  // at LutFigureInput::radius_px; NaN outside the written range
  std::optional<double> drop_px;    // where the ray stops increasing, if it does
  double distance_at_drop_cm = 0.0;
};

struct LutFigureInput {
  std::string title;              // the table's source and format
  std::string summary;            // the inspection's findings in one line
  std::vector<double> radius_px;  // the radii of the rays' bins
  double radius_end_px = 0.0;     // where the radius axis ends
  /// One per kLutFigureDirectionsDeg; nullopt where the table never wrote that direction.
  std::array<std::optional<LutProfile>, kLutFigureDirectionsDeg.size()> profiles;
  double largest_distance_cm = 0.0;  // over every direction's written range: scales the figure
  /// The radius where the first ray stops increasing, and what the marker there says.
  std::optional<double> monotonic_until_px;
  std::string monotonic_label;
  cv::Mat1f distance_image_cm;          // NaN where the table has no value
  Vec2 image_center_px = Vec2::Zero();  // the rays' origin in distance_image_cm
};

/// A BGR figure of the table.
cv::Mat plot_lut_figure(const LutFigureInput& lut);

}  // namespace ballsight
