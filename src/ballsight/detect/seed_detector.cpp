#include "ballsight/detect/seed_detector.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>
#include <string>

#include "ballsight/core/error.hpp"

namespace ballsight {

void HsvRange::validate(const char* name) const {
  static constexpr const char* kChannel[] = {"H", "S", "V"};
  static constexpr int kMax[] = {179, 255, 255};
  for (size_t c = 0; c < 3; ++c) {
    require(
        min[c] >= 0 && max[c] <= kMax[c], name,
        std::string(kChannel[c]) + " bounds must be within [0, " + std::to_string(kMax[c]) + "]");
    require(min[c] <= max[c], name, std::string(kChannel[c]) + " minimum exceeds maximum");
  }
}

namespace {

cv::Vec3b hsv_of(const cv::Vec3b& bgr) {
  cv::Mat3b pixel(1, 1, bgr), hsv;
  cv::cvtColor(pixel, hsv, cv::COLOR_BGR2HSV);
  return hsv(0, 0);
}

}  // namespace

bool HsvRange::contains_bgr(const cv::Vec3b& bgr) const {
  const cv::Vec3b hsv = hsv_of(bgr);
  for (int c = 0; c < 3; ++c) {
    if (hsv[c] < min[static_cast<size_t>(c)] || hsv[c] > max[static_cast<size_t>(c)]) return false;
  }
  return true;
}

int opencv_hue(const cv::Vec3b& bgr) {
  return hsv_of(bgr)[0];
}

HsvRange hue_moved(const HsvRange& range, const cv::Vec3b& from_bgr, const cv::Vec3b& to_bgr) {
  const int shift = opencv_hue(to_bgr) - opencv_hue(from_bgr);
  HsvRange moved = range;
  moved.min[0] = std::clamp(range.min[0] + shift, 0, 179);
  moved.max[0] = std::clamp(range.max[0] + shift, 0, 179);
  return moved;
}

void SeedDetectorOptions::validate() const {
  ball.validate("seed detector ball");
  front_marker.validate("seed detector front_marker");
  back_marker.validate("seed detector back_marker");
  require(median_kernel_px >= 1 && median_kernel_px % 2 == 1, "seed detector",
          "median_kernel_px must be an odd positive number");
}

namespace {

// Threshold, median filter, contours, centre of mass (section 7.1).
void detect_class(const cv::Mat& hsv, const HsvRange& range, int median_kernel_px,
                  ObjectClass object, std::vector<PixelDetection>& out) {
  cv::Mat1b mask;
  cv::inRange(hsv, cv::Scalar(range.min[0], range.min[1], range.min[2]),
              cv::Scalar(range.max[0], range.max[1], range.max[2]), mask);
  if (median_kernel_px > 1) cv::medianBlur(mask, mask, median_kernel_px);
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(mask, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
  for (const std::vector<cv::Point>& contour : contours) {
    const cv::Moments m = cv::moments(contour);
    PixelDetection d;
    d.object = object;
    if (m.m00 > 0.0) {
      d.center_px = Vec2(m.m10 / m.m00, m.m01 / m.m00);
    } else {  // a blob of one or two pixels (or a line) has no contour area: its points' mean
      for (const cv::Point& p : contour) d.center_px += Vec2(p.x, p.y);
      d.center_px /= static_cast<double>(contour.size());
    }
    d.area_px = std::max(m.m00, 1.0);
    d.radius_px = std::sqrt(d.area_px / std::numbers::pi);
    out.push_back(d);
  }
}

}  // namespace

std::vector<PixelDetection> detect_seed_colour(const cv::Mat& bgr, const HsvRange& range,
                                               int median_kernel_px, ObjectClass object) {
  range.validate("seed colour");
  require(median_kernel_px >= 1 && median_kernel_px % 2 == 1, "seed colour",
          "median_kernel_px must be an odd positive number");
  require(bgr.type() == CV_8UC3, "seed detector", "expected an 8-bit BGR image");
  cv::Mat hsv;
  cv::cvtColor(bgr, hsv, cv::COLOR_BGR2HSV);
  std::vector<PixelDetection> out;
  detect_class(hsv, range, median_kernel_px, object, out);
  std::stable_sort(out.begin(), out.end(), [](const PixelDetection& a, const PixelDetection& b) {
    return a.area_px > b.area_px;
  });
  return out;
}

std::vector<PixelDetection> detect_seed(const cv::Mat& bgr, const SeedDetectorOptions& options) {
  options.validate();
  require(bgr.type() == CV_8UC3, "seed detector", "expected an 8-bit BGR image");
  cv::Mat hsv;
  cv::cvtColor(bgr, hsv, cv::COLOR_BGR2HSV);
  std::vector<PixelDetection> out;
  detect_class(hsv, options.ball, options.median_kernel_px, ObjectClass::ball, out);
  detect_class(hsv, options.front_marker, options.median_kernel_px, ObjectClass::robot_front_marker,
               out);
  detect_class(hsv, options.back_marker, options.median_kernel_px, ObjectClass::robot_back_marker,
               out);
  return out;
}

}  // namespace ballsight
