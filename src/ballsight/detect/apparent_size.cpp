#include "ballsight/detect/apparent_size.hpp"

#include <cmath>

#include "ballsight/core/error.hpp"

namespace ballsight {

double apparent_radius_px(const FieldCamera& camera, const Vec3& center_in_field, double radius_m) {
  const std::optional<Vec2> center_px = camera.pixel_from_field(center_in_field);
  if (!center_px) return 0.0;
  const Vec3 sight = (center_in_field - camera.center_in_field()).normalized();
  Vec3 across = sight.cross(Vec3::UnitZ());
  if (across.norm() < 1e-9) across = Vec3::UnitX();
  across.normalize();
  const Vec3 up = across.cross(sight);
  double sum = 0.0;
  for (const Vec3& offset : {across, Vec3(-across), up, Vec3(-up)}) {
    const std::optional<Vec2> rim_px = camera.pixel_from_field(center_in_field + radius_m * offset);
    if (!rim_px) return 0.0;
    sum += (*rim_px - *center_px).norm();
  }
  return sum / 4.0;
}

ApparentSizeMap::ApparentSizeMap(const FieldCamera& camera, double radius_m, double center_height_m,
                                 const FieldRect& area, int cell_px)
    : cell_px_(cell_px) {
  require(radius_m > 0.0 && center_height_m >= 0.0, "apparent size",
          "need radius_m > 0 and center_height_m >= 0");
  require(area.valid(), "apparent size", "the field area must have a positive size");
  require(cell_px >= 1, "apparent size", "cell_px must be positive");
  const int cols = (camera.camera.width() + cell_px - 1) / cell_px;
  const int rows = (camera.camera.height() + cell_px - 1) / cell_px;
  radius_ = cv::Mat1f(rows, cols, 0.0f);
  for (int cy = 0; cy < rows; ++cy) {
    for (int cx = 0; cx < cols; ++cx) {
      const Vec2 pixel((cx + 0.5) * cell_px - 0.5, (cy + 0.5) * cell_px - 0.5);
      const std::optional<Vec3> center = camera.point_at_height(pixel, center_height_m);
      if (!center || !area.contains(center->head<2>())) continue;
      radius_(cy, cx) = static_cast<float>(apparent_radius_px(camera, *center, radius_m));
    }
  }
}

double ApparentSizeMap::radius_px(const Vec2& pixel) const {
  const int cx = static_cast<int>(std::floor((pixel.x() + 0.5) / cell_px_));
  const int cy = static_cast<int>(std::floor((pixel.y() + 0.5) / cell_px_));
  if (cx < 0 || cy < 0 || cx >= radius_.cols || cy >= radius_.rows) return 0.0;
  return radius_(cy, cx);
}

}  // namespace ballsight
