#pragma once
// GroundMap: ballsight's omnidirectional lookup table. One cell per image pixel holds the
// robot-local ground point {x_cm, y_cm} (x forward, y left) seen at that pixel, so a run-time
// conversion is one memory read; sub-pixel queries interpolate bilinearly. Any pixel -> ground
// mapping (a fitted model, an imported table, the simulator's truth) is baked into one with
// build_ground_map. File format: ground_map_io.hpp and docs/lut-format.md.

#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "ballsight/core/geometry.hpp"

namespace ballsight {

/// One table cell: the robot-local ground point in cm; both NaN where the table has no value.
struct GroundCell {
  float x_cm = std::numeric_limits<float>::quiet_NaN();
  float y_cm = std::numeric_limits<float>::quiet_NaN();

  bool valid() const { return !std::isnan(x_cm); }  // an invalid cell has both fields NaN
};
static_assert(sizeof(GroundCell) == 8, "a cell is one packed pair of floats");

/// Everything a table says about itself besides its cells (the file header).
struct GroundMapInfo {
  int width = 640;
  int height = 480;
  Vec2 image_center_px{319.5, 239.5};  // origin of the pixel radius of the valid range
  /// The valid range: pixels whose distance from image_center_px lies in this interval.
  double min_radius_px = 0.0;
  double max_radius_px = 240.0;
  std::string method = "unknown";  // which mapping built the table, e.g. "poly", "iris-px2cm"
  /// Height of the camera's effective viewpoint above the floor, when the method knows it (a
  /// fitted catadioptric model does); 0 = unknown. Run time needs it to place a ball's centre.
  double viewpoint_height_cm = 0.0;

  static constexpr std::size_t kMaxMethodLength = 63;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// Any pixel -> ground mapping: the robot-local ground point in cm, nullopt where undefined.
using PixelToGroundCm = std::function<std::optional<Vec2>(const Vec2& pixel)>;

class GroundMap {
 public:
  /// `cells` row-major, width * height of them; throws InputError when the count is wrong.
  GroundMap(GroundMapInfo info, std::vector<GroundCell> cells);

  const GroundMapInfo& info() const { return info_; }
  int width() const { return info_.width; }
  int height() const { return info_.height; }
  std::span<const GroundCell> cells() const { return cells_; }

  /// The run-time conversion: one read of the cell at integer pixel (x, y); an invalid (NaN)
  /// cell outside the image.
  GroundCell at(int x, int y) const {
    if (static_cast<unsigned>(x) >= static_cast<unsigned>(info_.width) ||
        static_cast<unsigned>(y) >= static_cast<unsigned>(info_.height)) {
      return {};
    }
    return cells_[static_cast<std::size_t>(y) * static_cast<std::size_t>(info_.width) +
                  static_cast<std::size_t>(x)];
  }

  /// Whether a (sub-)pixel lies in the valid range of radii around the image centre.
  bool in_valid_range(const Vec2& pixel) const;

  /// Sub-pixel conversion: bilinear interpolation of the four cells around `pixel` (pixel
  /// centres at integer coordinates); nullopt outside the valid range or next to an invalid cell.
  std::optional<Vec2> robot_point_cm(const Vec2& pixel) const;

 private:
  GroundMapInfo info_;
  std::vector<GroundCell> cells_;
};

/// Bakes `mapping` into a table. Cells are stored for every pixel within sqrt(2) px of the
/// valid range (so that every sub-pixel query inside the range has its four cells) where the
/// mapping is defined; all other cells are invalid.
GroundMap build_ground_map(const PixelToGroundCm& mapping, const GroundMapInfo& info);

}  // namespace ballsight
