#include "ballsight/camera/ground_map.hpp"

#include <cmath>
#include <numbers>

#include "ballsight/core/error.hpp"

namespace ballsight {

void GroundMapInfo::validate() const {
  const std::string where = "ground map";
  require(width >= 1 && height >= 1 && width <= 8192 && height <= 8192, where,
          "image size must be between 1 and 8192 px, got " + std::to_string(width) + "x" +
              std::to_string(height));
  require(image_center_px.allFinite(), where, "image_center_px must be finite");
  require(std::isfinite(min_radius_px) && min_radius_px >= 0.0, where,
          "min_radius_px must be >= 0");
  require(std::isfinite(max_radius_px) && max_radius_px > min_radius_px, where,
          "max_radius_px must be > min_radius_px");
  require(std::isfinite(viewpoint_height_cm) && viewpoint_height_cm >= 0.0 &&
              viewpoint_height_cm < 4.0e7,
          where, "viewpoint_height_cm must be >= 0 (0 = unknown)");
  require(method.size() <= kMaxMethodLength, where,
          "method must be at most " + std::to_string(kMaxMethodLength) + " characters");
}

GroundMap::GroundMap(GroundMapInfo info, std::vector<GroundCell> cells)
    : info_(std::move(info)), cells_(std::move(cells)) {
  info_.validate();
  require(cells_.size() == static_cast<std::size_t>(info_.width) * info_.height, "ground map",
          "expected " + std::to_string(info_.width) + "x" + std::to_string(info_.height) +
              " cells, got " + std::to_string(cells_.size()));
}

bool GroundMap::in_valid_range(const Vec2& pixel) const {
  const double r = (pixel - info_.image_center_px).norm();
  return r >= info_.min_radius_px && r <= info_.max_radius_px;
}

std::optional<Vec2> GroundMap::robot_point_cm(const Vec2& pixel) const {
  if (!in_valid_range(pixel)) return std::nullopt;
  const double fx = std::floor(pixel.x());
  const double fy = std::floor(pixel.y());
  if (fx < -1.0 || fy < -1.0 || fx >= info_.width || fy >= info_.height) return std::nullopt;
  const int x0 = static_cast<int>(fx);
  const int y0 = static_cast<int>(fy);
  const GroundCell c00 = at(x0, y0), c10 = at(x0 + 1, y0);
  const GroundCell c01 = at(x0, y0 + 1), c11 = at(x0 + 1, y0 + 1);
  if (!c00.valid() || !c10.valid() || !c01.valid() || !c11.valid()) return std::nullopt;
  const double ax = pixel.x() - fx;
  const double ay = pixel.y() - fy;
  const auto lerp2 = [&](float v00, float v10, float v01, float v11) {
    return (1.0 - ay) * ((1.0 - ax) * v00 + ax * v10) + ay * ((1.0 - ax) * v01 + ax * v11);
  };
  return Vec2(lerp2(c00.x_cm, c10.x_cm, c01.x_cm, c11.x_cm),
              lerp2(c00.y_cm, c10.y_cm, c01.y_cm, c11.y_cm));
}

GroundMap build_ground_map(const PixelToGroundCm& mapping, const GroundMapInfo& info) {
  info.validate();
  // A query inside the range reads cells up to sqrt(2) px away from it.
  const double apron_px = std::numbers::sqrt2;
  const double lo = std::max(0.0, info.min_radius_px - apron_px);
  const double hi = info.max_radius_px + apron_px;
  std::vector<GroundCell> cells(static_cast<std::size_t>(info.width) * info.height);
  for (int y = 0; y < info.height; ++y) {
    for (int x = 0; x < info.width; ++x) {
      const Vec2 pixel(x, y);
      const double r = (pixel - info.image_center_px).norm();
      if (r < lo || r > hi) continue;
      const std::optional<Vec2> p_cm = mapping(pixel);
      if (!p_cm || !p_cm->allFinite()) continue;
      cells[static_cast<std::size_t>(y) * info.width + x] = {static_cast<float>(p_cm->x()),
                                                             static_cast<float>(p_cm->y())};
    }
  }
  return GroundMap(info, std::move(cells));
}

}  // namespace ballsight
