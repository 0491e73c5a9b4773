#include "ballsight/calib/chessboard_corners.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "ballsight/core/error.hpp"

namespace ballsight {

void ChessboardPattern::validate() const {
  require(inner_cols >= 3 && inner_rows >= 3, "board",
          "expected at least 3x3 inner corners, got " + std::to_string(inner_cols) + "x" +
              std::to_string(inner_rows));
  require(inner_cols != inner_rows, "board",
          "inner corner counts must differ (one even and one odd side) so that the board's "
          "orientation is unambiguous");
  require(std::isfinite(square_m) && square_m > 0.0, "square", "must be a positive length");
}

std::vector<cv::Point3f> ChessboardPattern::object_points() const {
  std::vector<cv::Point3f> points;
  for (int r = 0; r < inner_rows; ++r) {
    for (int c = 0; c < inner_cols; ++c) {
      points.emplace_back(static_cast<float>(c * square_m), static_cast<float>(r * square_m), 0.f);
    }
  }
  return points;
}

namespace {

// Shortest distance between neighbouring corners along rows and columns, px.
double smallest_spacing_px(const std::vector<cv::Point2f>& corners, cv::Size pattern) {
  double spacing = 1e9;
  for (int r = 0; r < pattern.height; ++r) {
    for (int c = 0; c < pattern.width; ++c) {
      const cv::Point2f& p = corners[static_cast<std::size_t>(r * pattern.width + c)];
      if (c + 1 < pattern.width) {
        spacing = std::min(
            spacing, cv::norm(corners[static_cast<std::size_t>(r * pattern.width + c + 1)] - p));
      }
      if (r + 1 < pattern.height) {
        spacing = std::min(
            spacing, cv::norm(corners[static_cast<std::size_t>((r + 1) * pattern.width + c)] - p));
      }
    }
  }
  return spacing;
}

}  // namespace

std::optional<std::vector<cv::Point2f>> find_chessboard_corners(const cv::Mat& image,
                                                                const ChessboardPattern& pattern) {
  pattern.validate();
  cv::Mat grey = image;
  if (image.channels() == 3) cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  std::vector<cv::Point2f> corners;
  if (!cv::findChessboardCorners(grey, pattern.pattern_size(), corners,
                                 cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE)) {
    return std::nullopt;
  }
  // The refinement window (half-size) must stay inside the squares around a corner: a third of
  // the smallest corner spacing, 2 to 11 px (OpenCV's calibration sample uses 11 on 640x480).
  const int half = std::clamp(
      static_cast<int>(smallest_spacing_px(corners, pattern.pattern_size()) / 3.0), 2, 11);
  cv::cornerSubPix(grey, corners, cv::Size(half, half), cv::Size(-1, -1),
                   cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 50, 1e-3));
  return corners;
}

}  // namespace ballsight
