#pragma once
// Seeded board poses for a chessboard calibration session: the whole board in view, tilted up to
// ~45 degrees, spun a little about its normal, filling 20-70% of the image and spread over the
// whole image (corners included, where the lens distorts most).

#include <cstdint>
#include <vector>

#include "ballsight/camera/pinhole.hpp"
#include "ballsight/core/geometry.hpp"
#include "ballsight/sim/chessboard.hpp"

namespace ballsight::sim {

struct ChessboardPoseOptions {
  double max_tilt_deg = 45.0;  // rotation of the board's normal away from the camera axis
  double max_spin_deg = 20.0;  // rotation about the board's normal (keeps rows roughly level)
  double min_fill = 0.2;       // projected board size / image size, the larger of the two axes
  double max_fill = 0.7;
  double margin_px = 8.0;            // the board's outline stays this far inside the image
  double max_view_angle_deg = 65.0;  // between a viewing ray and the board's normal

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// `count` poses (camera_from_board); deterministic for a seed. Throws InputError when the board
/// cannot be placed as asked (e.g. too large for the field of view).
std::vector<Rigid3> make_chessboard_poses(const PinholeCamera& camera, const ChessboardSpec& board,
                                          int count, const ChessboardPoseOptions& options,
                                          std::uint64_t seed);

/// Projected size of the board: max(bounding-box width / image width, height / image height).
double chessboard_fill(const PinholeCamera& camera, const std::vector<Vec2>& outline_pixels);

}  // namespace ballsight::sim
