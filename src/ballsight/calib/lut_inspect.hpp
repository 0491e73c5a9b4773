#pragma once
// Inspection of omnidirectional lookup tables (`ballsight omni inspect`): a table of either
// format is read as ground distance along 360 rays from its image centre, and each ray is
// checked for where it was first written, where it stops increasing, and holes; directions are
// compared at a few radii. The paper's tables (shared/data/iris-lut) stop being monotonic past
// ~175-210 px, where the network extrapolates beyond its training markers.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ballsight/camera/ground_map.hpp"
#include "ballsight/camera/iris_lut.hpp"

namespace ballsight {

enum class LutFormat { automatic, ballsight, iris_px2cm };

/// "auto", "ballsight" or "iris-px2cm"; throws InputError otherwise.
LutFormat lut_format_from_string(std::string_view name);
std::string_view to_string(LutFormat format);

/// Ground distance along rays from a table's image centre: direction theta_deg = 0 .. 359 (image
/// angle, counter-clockwise from the image's right), radius bin / bins_per_px.
struct RadialTable {
  static constexpr int kDirections = 360;
  double bins_per_px = 10.0;
  int bins = 0;
  std::vector<float> distance_cm;  // [theta_deg * bins + bin]; NaN where the table has no value

  std::span<const float> ray(int theta_deg) const;
  double radius_px(int bin) const { return bin / bins_per_px; }
  /// The bin nearest to `radius_px`.
  int bin_at(double radius_px) const;
};

/// A table read for inspection: its rays and its ground distance at every image pixel.
struct InspectedLut {
  std::string source;
  LutFormat format = LutFormat::automatic;  // as resolved
  RadialTable rays;
  cv::Mat1f distance_image_cm;          // NaN where the table has no value
  Vec2 image_center_px = Vec2::Zero();  // the rays' origin in distance_image_cm
};

/// The px2cm table's own layout, entries as they are (unwritten ones too); the image is the
/// robots' read over a 640 x 640 square around the table's centre.
InspectedLut inspected_from_iris(const IrisLut& px2cm, std::string source);
/// Interpolated ground distances (GroundMap::robot_point_cm) along the rays at 0.1 px steps;
/// the image is the distance of every cell.
InspectedLut inspected_from_ground_map(const GroundMap& map, std::string source);

/// Reads `path` in `format`; `automatic` picks ballsight by its magic and iris px2cm by its
/// size. Throws InputError naming the file when it cannot be read or recognised.
InspectedLut read_lut_for_inspection(const std::filesystem::path& path, LutFormat format);

struct LutInspectOptions {
  /// A value more than this below the running maximum along a ray breaks monotonicity.
  double drop_tolerance_cm = 5.0;
  /// Plausible ground distances are in (0, max_plausible_cm]; others are holes or unwritten.
  double max_plausible_cm = 3000.0;
  /// A ray is written from the first run this long of plausible, non-decreasing values.
  double confirm_run_px = 2.0;
  /// Radii at which directions are compared.
  std::vector<double> spread_radii_px{100.0, 150.0, 175.0, 200.0, 250.0};

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// What one ray shows; radii in px, nullopt where the ray was never written.
struct RayFindings {
  std::optional<double> first_written_px;
  std::optional<double> last_written_px;
  /// The first radius whose distance lies more than the tolerance below the running maximum;
  /// nullopt when the ray is monotonic over its whole written range.
  std::optional<double> drop_px;
  int holes = 0;  // implausible entries between first and last written
};

struct RadiusSpread {
  double radius_px = 0.0;
  int directions = 0;  // directions with a plausible written value at this radius
  double min_cm = 0.0, max_cm = 0.0;
  double spread_cm() const { return max_cm - min_cm; }
};

struct LutInspection {
  std::string source;
  std::string format;
  double radius_step_px = 0.1;
  int bins = 0;
  double drop_tolerance_cm = 5.0;
  std::vector<RayFindings> rays;  // one per direction, theta_deg = index

  // Over the written directions:
  int written_directions = 0;
  std::optional<double> first_written_min_px, first_written_median_px, first_written_max_px;
  std::optional<double> last_written_min_px, last_written_max_px;
  /// The smallest radius over all directions at which a ray stops increasing (its drop, or the
  /// end of its written range when it never drops), and the direction that has it.
  std::optional<double> monotonic_until_px;
  int monotonic_until_theta_deg = 0;
  int non_monotonic_directions = 0;
  std::vector<RadiusSpread> spread;  // at the options' radii inside the table
  long long holes = 0;
  long long written_bins = 0;
  int directions_with_holes = 0;
};

/// Analyses every ray of `lut` (definitions in LutInspectOptions and RayFindings).
LutInspection inspect_lut(const InspectedLut& lut, const LutInspectOptions& options = {});

/// Machine-readable report; the keys are those of the text report.
nlohmann::ordered_json to_json(const LutInspection& inspection);
/// A short aligned text report, one finding per line.
std::string format_report(const LutInspection& inspection);

}  // namespace ballsight
