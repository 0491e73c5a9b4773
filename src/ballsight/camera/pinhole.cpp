#include "ballsight/camera/pinhole.hpp"

#include <cmath>
#include <string>

#include "ballsight/core/error.hpp"

namespace ballsight {

void PinholeParams::validate() const {
  require(width > 0 && height > 0, "pinhole camera", "image size must be positive");
  require(std::isfinite(fx) && fx > 0.0 && std::isfinite(fy) && fy > 0.0, "pinhole camera",
          "focal lengths fx, fy must be positive");
  require(std::isfinite(cx) && std::isfinite(cy), "pinhole camera",
          "principal point must be finite");
}

PinholeCamera::PinholeCamera(const PinholeParams& params)
    : params_(params), distortion_((params.validate(), params.distortion)) {}

std::optional<Vec2> PinholeCamera::project(const Vec3& p_in_camera) const {
  if (!(p_in_camera.z() > 0.0)) return std::nullopt;
  const Vec2 m = p_in_camera.head<2>() / p_in_camera.z();
  if (m.norm() > distortion_.max_radius()) return std::nullopt;
  const Vec2 md = distortion_.distort(m);
  return Vec2(params_.fx * md.x() + params_.cx, params_.fy * md.y() + params_.cy);
}

std::optional<Vec3> PinholeCamera::unproject(const Vec2& pixel) const {
  const Vec2 md((pixel.x() - params_.cx) / params_.fx, (pixel.y() - params_.cy) / params_.fy);
  const std::optional<Vec2> m = distortion_.undistort(md);
  if (!m) return std::nullopt;
  return Vec3(m->x(), m->y(), 1.0).normalized();
}

bool PinholeCamera::in_image(const Vec2& pixel) const {
  return pixel.x() >= -0.5 && pixel.y() >= -0.5 && pixel.x() < params_.width - 0.5 &&
         pixel.y() < params_.height - 0.5;
}

cv::Matx33d PinholeCamera::camera_matrix() const {
  return {params_.fx, 0.0, params_.cx, 0.0, params_.fy, params_.cy, 0.0, 0.0, 1.0};
}

cv::Mat PinholeCamera::distortion_coefficients() const {
  cv::Mat d(1, 8, CV_64F);
  for (int i = 0; i < 8; ++i) d.at<double>(i) = params_.distortion[static_cast<size_t>(i)];
  return d;
}

PinholeCamera PinholeCamera::from_opencv(const cv::Matx33d& k, const cv::Mat& distortion,
                                         cv::Size image_size) {
  const int n = static_cast<int>(distortion.total());
  require(distortion.empty() || n == 4 || n == 5 || n == 8, "distortion_coefficients",
          "expected 4, 5 or 8 values, got " + std::to_string(n));
  PinholeParams p;
  p.width = image_size.width;
  p.height = image_size.height;
  p.fx = k(0, 0);
  p.fy = k(1, 1);
  p.cx = k(0, 2);
  p.cy = k(1, 2);
  cv::Mat d;
  distortion.convertTo(d, CV_64F);
  for (int i = 0; i < n; ++i) p.distortion[static_cast<size_t>(i)] = d.at<double>(i);
  return PinholeCamera(p);
}

}  // namespace ballsight
