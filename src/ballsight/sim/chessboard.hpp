#pragma once
// A printed chessboard seen by a pinhole camera, for intrinsic calibration (the chessboard step of
// the tennis-ball-collecting-robot report, section 7.2): the board spec, a supersampled rendering
// through the distorted lens and the true pixels of its inner corners.
//
// Board frame: origin at the first inner corner, x along a row of inner corners, y down the
// columns, z = x cross y, pointing away from a camera that sees the printed side. Squares alternate
// from a black square in the top-left corner; a white border surrounds the squares.

#include <cstdint>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "ballsight/camera/pinhole.hpp"
#include "ballsight/core/geometry.hpp"
#include "ballsight/sim/image_effects.hpp"
#include "ballsight/sim/ray_table.hpp"

namespace ballsight::sim {

struct ChessboardSpec {
  int inner_cols = 9;  // inner corners per row (OpenCV's patternSize.width)
  int inner_rows = 6;  // inner corners per column (patternSize.height)
  double square_m = 0.05;
  double border_m = 0.04;  // white margin around the squares

  /// Throws InputError naming the first invalid field.
  void validate() const;
  /// Inner corners in the board frame, row by row (OpenCV's order), z = 0.
  std::vector<Vec3> inner_corners() const;
  /// The board's outline (outer edge of the border) in the board frame: x_min, y_min, x_max, y_max.
  cv::Rect2d outline() const;
};

struct ChessboardRenderOptions {
  int samples_per_axis = 4;  // supersampling per pixel inside the board
  double black = 30.0;       // grey levels of the print and the background
  double white = 225.0;
  double background = 110.0;
  ImageEffects effects;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// Renders the board at `camera_from_board` through `camera`; `rays` must be the camera's ray table
/// in the camera frame. BGR image (grey), noise seeded by `noise_seed`.
cv::Mat render_chessboard(const PinholeCamera& camera, const RayTable& rays,
                          const ChessboardSpec& board, const Rigid3& camera_from_board,
                          const ChessboardRenderOptions& options, std::uint64_t noise_seed);

/// Pixels of the inner corners (inner_corners() order); nullopt if any fails to project.
std::optional<std::vector<Vec2>> chessboard_corner_pixels(const PinholeCamera& camera,
                                                          const ChessboardSpec& board,
                                                          const Rigid3& camera_from_board);

/// Pixels along the board's outline (`per_side` points per side); nullopt if any fails to project.
std::optional<std::vector<Vec2>> chessboard_outline_pixels(const PinholeCamera& camera,
                                                           const ChessboardSpec& board,
                                                           const Rigid3& camera_from_board,
                                                           int per_side = 16);

}  // namespace ballsight::sim
