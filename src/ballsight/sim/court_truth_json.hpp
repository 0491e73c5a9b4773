#pragma once
// The simulator's truth as JSON (nlohmann), documented field by field in docs/sim-court.md:
// one file per court scene and one for a chessboard session.

#include <cstdint>
#include <string>
#include <vector>

#include "ballsight/camera/pinhole.hpp"
#include "ballsight/core/geometry.hpp"
#include "ballsight/sim/chessboard.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "ballsight/sim/court_scene.hpp"
#include "ballsight/sim/court_truth.hpp"
#include "ballsight/sim/json_io.hpp"

namespace ballsight::sim {

inline constexpr int kCourtTruthVersion =
    4;  // 2: the net; 3: light, leaves, bottles, colours; 4: obstacles

/// {"rvec", "tvec", "rotation"} of a rigid transform (OpenCV's rvec; rotation row by row).
Json rigid3_json(const Rigid3& transform);
/// Image size, fx, fy, cx, cy and the 8 distortion coefficients in OpenCV's order.
Json intrinsics_json(const PinholeCamera& camera);

/// One court scene: installation, cameras with their images, lighting, robot and every object
/// with its per-camera truth. `image_files[i]` is camera i's image, relative to the JSON file.
Json court_scene_json(const CourtRig& rig, const CourtScene& scene,
                      const std::vector<SphereTruth>& truth,
                      const std::vector<std::string>& image_files, std::uint64_t seed,
                      int scene_index);

/// One camera's chessboard views: intrinsics, board poses, image files and inner-corner pixels.
struct ChessboardViewTruth {
  std::string image_file;
  Rigid3 camera_from_board;
  std::vector<Vec2> corners_px;
};
Json chessboard_camera_json(const PinholeCamera& camera, int camera_index,
                            const std::vector<ChessboardViewTruth>& views);
/// The chessboard session: board spec and the cameras (from chessboard_camera_json).
Json chessboard_session_json(const ChessboardSpec& board, std::uint64_t seed,
                             const std::vector<Json>& cameras);

}  // namespace ballsight::sim
