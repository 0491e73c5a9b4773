#pragma once
// The unified central catadioptric camera (Mei & Rives 2007), as cv::omnidir implements it: the
// unified model (unified_model.hpp: onto the unit sphere, then through a pinhole shifted by `xi`
// along the axis), then the lens (k1, k2, p1, p2) and the camera matrix. Camera frame as
// OpenCV's.

#include <optional>

#include "ballsight/camera/distortion.hpp"
#include "ballsight/camera/unified_model.hpp"
#include "ballsight/core/geometry.hpp"

namespace ballsight {

struct UnifiedParams {
  int width = 0;
  int height = 0;
  double xi = 1.0;
  double fx = 0.0, fy = 0.0, cx = 0.0, cy = 0.0;
  double k1 = 0.0, k2 = 0.0, p1 = 0.0, p2 = 0.0;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

class UnifiedCamera {
 public:
  explicit UnifiedCamera(const UnifiedParams& params);

  const UnifiedParams& params() const { return params_; }
  int width() const { return params_.width; }
  int height() const { return params_.height; }

  /// Point in the camera frame -> pixel; nullopt where the model has no unique projection.
  std::optional<Vec2> project(const Vec3& p_in_camera) const;
  /// Pixel -> unit ray in the camera frame; nullopt outside the model's image.
  std::optional<Vec3> unproject(const Vec2& pixel) const;

 private:
  UnifiedParams params_;
  UnifiedModel<double> model_;
  Distortion distortion_;
};

}  // namespace ballsight
