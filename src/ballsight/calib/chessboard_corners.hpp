#pragma once
// Chessboard inner corners in an image for intrinsic calibration (the chessboard step of the
// tennis-ball-collecting-robot report, section 7.2): OpenCV's detector, then sub-pixel refinement
// with a window sized to the board's squares in the image.

#include <opencv2/core.hpp>
#include <optional>
#include <vector>

namespace ballsight {

/// A printed chessboard: inner corners per row and per column (OpenCV's patternSize) and the
/// side of a square. One side with an even and one with an odd number of squares makes the
/// board's orientation unambiguous.
struct ChessboardPattern {
  int inner_cols = 9;
  int inner_rows = 6;
  double square_m = 0.025;

  /// Throws InputError naming the first invalid field.
  void validate() const;
  cv::Size pattern_size() const { return {inner_cols, inner_rows}; }
  /// Inner corners in the board frame (z = 0), row by row as OpenCV lists them.
  std::vector<cv::Point3f> object_points() const;
};

/// The inner corners (OpenCV's order) refined to sub-pixel, or nullopt when the whole board is
/// not found. `image` is grey or BGR.
std::optional<std::vector<cv::Point2f>> find_chessboard_corners(const cv::Mat& image,
                                                                const ChessboardPattern& pattern);

}  // namespace ballsight
