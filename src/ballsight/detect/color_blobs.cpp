#include "ballsight/detect/color_blobs.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "ballsight/core/error.hpp"

namespace ballsight {

void ColorBlobOptions::validate() const {
  require(std::isfinite(hue_tolerance_deg) && hue_tolerance_deg > 0.0 && hue_tolerance_deg < 180.0,
          "hue_tolerance_deg", "must be in (0, 180)");
  require(std::isfinite(min_saturation) && min_saturation >= 0.0 && min_saturation <= 1.0,
          "min_saturation", "must be in [0, 1]");
  require(std::isfinite(min_value) && min_value >= 0.0 && min_value <= 1.0, "min_value",
          "must be in [0, 1]");
  require(min_area_px >= 1 && max_area_px >= min_area_px, "min_area_px",
          "need 1 <= min_area_px <= max_area_px");
}

namespace {

// Chroma of a BGR colour in an opponent plane (R - G, (R + G)/2 - B): mixing colours mixes their
// chroma linearly, so a pixel's share of the target colour is its chroma's projection on it.
Vec2 chroma(const cv::Vec3b& bgr) {
  const double b = bgr[0], g = bgr[1], r = bgr[2];
  return {r - g, 0.5 * (r + g) - b};
}

}  // namespace

std::vector<ColorBlob> find_color_blobs(const cv::Mat& bgr, const ColorBlobOptions& options) {
  options.validate();
  require(bgr.type() == CV_8UC3 && !bgr.empty(), "color blobs", "expected a BGR image");
  cv::Mat hsv;
  cv::cvtColor(bgr, hsv, cv::COLOR_BGR2HSV_FULL);  // hue 0-255 over the whole circle
  cv::Mat target_hsv;
  cv::cvtColor(
      cv::Mat(1, 1, CV_8UC3,
              cv::Scalar(options.target_bgr[0], options.target_bgr[1], options.target_bgr[2])),
      target_hsv, cv::COLOR_BGR2HSV_FULL);
  const int target_hue = target_hsv.at<cv::Vec3b>(0, 0)[0];
  const double hue_tolerance = options.hue_tolerance_deg * 256.0 / 360.0;
  const double min_s = options.min_saturation * 255.0, min_v = options.min_value * 255.0;

  cv::Mat1b mask(bgr.size(), 0);
  for (int y = 0; y < hsv.rows; ++y) {
    const cv::Vec3b* row = hsv.ptr<cv::Vec3b>(y);
    std::uint8_t* out = mask.ptr<std::uint8_t>(y);
    for (int x = 0; x < hsv.cols; ++x) {
      const int dh = std::abs(row[x][0] - target_hue);
      const int hue_distance = std::min(dh, 256 - dh);
      out[x] =
          (hue_distance <= hue_tolerance && row[x][1] >= min_s && row[x][2] >= min_v) ? 255 : 0;
    }
  }
  cv::Mat labels, stats, centroids;
  const int count = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8, CV_32S);

  const Vec2 target = chroma(options.target_bgr);
  const Vec2 unit = target.normalized();
  std::vector<ColorBlob> blobs;
  for (int label = 1; label < count; ++label) {
    const int area = stats.at<int>(label, cv::CC_STAT_AREA);
    if (area < options.min_area_px || area > options.max_area_px) continue;
    ColorBlob blob;
    blob.area_px = area;
    blob.bbox = {stats.at<int>(label, cv::CC_STAT_LEFT), stats.at<int>(label, cv::CC_STAT_TOP),
                 stats.at<int>(label, cv::CC_STAT_WIDTH), stats.at<int>(label, cv::CC_STAT_HEIGHT)};
    // Weighted centroid over the blob grown by one pixel: the mixed pixels at its rim count by
    // their share of the colour.
    const cv::Rect window =
        (blob.bbox + cv::Size(2, 2) - cv::Point(1, 1)) & cv::Rect(0, 0, bgr.cols, bgr.rows);
    Vec2 sum = Vec2::Zero();
    double weight_sum = 0.0;
    for (int y = window.y; y < window.y + window.height; ++y) {
      for (int x = window.x; x < window.x + window.width; ++x) {
        const double w =
            std::clamp(chroma(bgr.at<cv::Vec3b>(y, x)).dot(unit) / target.norm(), 0.0, 1.0);
        sum += w * Vec2(x, y);
        weight_sum += w;
      }
    }
    blob.centroid_px = weight_sum > 0.0
                           ? Vec2(sum / weight_sum)
                           : Vec2(centroids.at<double>(label, 0), centroids.at<double>(label, 1));
    blobs.push_back(blob);
  }
  std::stable_sort(blobs.begin(), blobs.end(),
                   [](const ColorBlob& a, const ColorBlob& b) { return a.area_px > b.area_px; });
  return blobs;
}

}  // namespace ballsight
