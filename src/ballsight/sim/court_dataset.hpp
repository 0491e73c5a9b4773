#pragma once
// A simulated court data set on disk: for each scene one PNG per camera and one truth JSON, and
// optionally a chessboard session per camera (PNGs and one truth JSON). What `ballsight sim court`
// writes; the layout and the JSON are documented in docs/sim-court.md.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "ballsight/sim/chessboard.hpp"
#include "ballsight/sim/chessboard_poses.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "ballsight/sim/court_scenario.hpp"
#include "ballsight/sim/tennis_court.hpp"

namespace ballsight::sim {

struct CourtDatasetOptions {
  std::uint64_t seed = 1;
  int scenes = 1;
  int chessboard_views = 0;  // per camera
  TennisCourtSpec court;     // with its net unless court.net.enabled is false
  CourtRigOptions rig;
  CourtScenarioOptions scenario;
  ChessboardSpec board;
  ChessboardPoseOptions board_poses;

  static constexpr int kMaxScenes = 9999;
  static constexpr int kMaxChessboardViews = 99;
  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// Writes the data set into `out_dir` (created if missing); returns the file names written, in
/// order. Same options, same bytes.
std::vector<std::string> write_court_dataset(const CourtDatasetOptions& options,
                                             const std::filesystem::path& out_dir);

}  // namespace ballsight::sim
