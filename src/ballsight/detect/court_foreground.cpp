#include "ballsight/detect/court_foreground.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "ballsight/core/error.hpp"

namespace ballsight {

void ForegroundOptions::validate() const {
  require(threshold >= 1 && threshold <= 765, "foreground threshold", "must be in [1, 765]");
  require(std::isfinite(min_area_px) && min_area_px >= 0.0, "foreground min_area_px",
          "must be at least 0");
}

CourtForeground::CourtForeground(const cv::Mat& empty_court, const ForegroundOptions& options)
    : options_(options), size_(empty_court.size()) {
  options_.validate();
  require(empty_court.type() == CV_8UC3 && !empty_court.empty(), "empty court view",
          "must be an 8-bit BGR image");
  background_ = half(empty_court);
}

cv::Mat CourtForeground::half(const cv::Mat& bgr) const {
  cv::Mat small(bgr.rows / 2, bgr.cols / 2, CV_8UC3);
  for (int y = 0; y < small.rows; ++y) {
    const auto* in = bgr.ptr<cv::Vec3b>(2 * y);
    auto* out = small.ptr<cv::Vec3b>(y);
    for (int x = 0; x < small.cols; ++x) out[x] = in[2 * x];
  }
  return small;
}

std::vector<PixelDetection> CourtForeground::detect(const cv::Mat& frame) const {
  require(frame.size() == size_ && frame.type() == CV_8UC3, "foreground frame",
          "must be the empty court view's size, 8-bit BGR");
  // The colour distance of every other pixel of every other row (the sum of the channels'
  // differences: in shade, where every colour is dark, a change shows in all three at once).
  cv::Mat1b mask(background_.rows, background_.cols);
  for (int y = 0; y < mask.rows; ++y) {
    const auto* in = frame.ptr<cv::Vec3b>(2 * y);
    const auto* empty = background_.ptr<cv::Vec3b>(y);
    auto* out = mask.ptr<uchar>(y);
    for (int x = 0; x < mask.cols; ++x) {
      const cv::Vec3b& a = in[2 * x];
      const cv::Vec3b& b = empty[x];
      const int distance = std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]);
      out[x] = distance > options_.threshold ? 255 : 0;
    }
  }
  cv::morphologyEx(mask, mask, cv::MORPH_OPEN, cv::Mat1b::ones(3, 3));  // specks of noise off
  cv::Mat labels, stats, centroids;
  const int count = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8, CV_32S);
  std::vector<PixelDetection> out;
  for (int label = 1; label < count; ++label) {
    const double area = 4.0 * stats.at<int>(label, cv::CC_STAT_AREA);  // full resolution
    if (area < options_.min_area_px) continue;
    const int left = stats.at<int>(label, cv::CC_STAT_LEFT),
              top = stats.at<int>(label, cv::CC_STAT_TOP);
    const int width = stats.at<int>(label, cv::CC_STAT_WIDTH),
              height = stats.at<int>(label, cv::CC_STAT_HEIGHT);
    PixelDetection d;
    d.object = ObjectClass::obstacle;
    d.center_px = 2.0 * Vec2(centroids.at<double>(label, 0), centroids.at<double>(label, 1)) +
                  Vec2::Constant(0.5);
    d.area_px = area;
    d.radius_px = std::sqrt(area / M_PI);
    d.patch.x = 2 * left;
    d.patch.y = 2 * top;
    d.patch.width = std::min(2 * width, size_.width - d.patch.x);
    d.patch.height = std::min(2 * height, size_.height - d.patch.y);
    d.patch.blob = label - 1;
    d.patch.coverage.resize(static_cast<std::size_t>(d.patch.width) * d.patch.height);
    for (int py = 0; py < d.patch.height; ++py) {
      const int* row = labels.ptr<int>(top + py / 2);
      for (int px = 0; px < d.patch.width; ++px)
        d.patch.coverage[static_cast<std::size_t>(py) * d.patch.width + px] =
            row[left + px / 2] == label ? 1.0f : 0.0f;
    }
    out.push_back(std::move(d));
  }
  std::sort(out.begin(), out.end(),
            [](const PixelDetection& a, const PixelDetection& b) { return a.area_px > b.area_px; });
  return out;
}

}  // namespace ballsight
