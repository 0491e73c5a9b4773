#pragma once
// How large a sphere of known radius, resting at a known centre height, appears at each place of a
// fixed camera's image: the size check of the court detector, and where it needs to look at all
// (0 where the camera's rays do not meet that height inside the field area).

#include <opencv2/core.hpp>

#include "ballsight/camera/field_camera.hpp"
#include "ballsight/core/field_rect.hpp"

namespace ballsight {

class ApparentSizeMap {
 public:
  /// Samples the camera at the centre of every `cell_px` x `cell_px` cell of the image.
  ApparentSizeMap(const FieldCamera& camera, double radius_m, double center_height_m,
                  const FieldRect& area, int cell_px = 16);

  /// Apparent radius (pixels) of the sphere centred on the ray through `pixel`; 0 where that ray
  /// does not meet the centre height inside the area, or outside the image.
  double radius_px(const Vec2& pixel) const;
  double radius_px_at_cell(int cell_x, int cell_y) const { return radius_(cell_y, cell_x); }
  int cell_px() const { return cell_px_; }
  cv::Size grid_size() const { return radius_.size(); }

 private:
  int cell_px_;
  cv::Mat1f radius_;
};

/// Apparent radius of a sphere of `radius_m` centred at `center_in_field` (mean pixel distance
/// from its centre's image to the images of four points one radius away across the line of
/// sight); 0 where it does not project.
double apparent_radius_px(const FieldCamera& camera, const Vec3& center_in_field, double radius_m);

}  // namespace ballsight
