#include "ballsight/sim/court_dataset.hpp"

#include <cstdio>

#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/sim/court_renderer.hpp"
#include "ballsight/sim/court_truth.hpp"
#include "ballsight/sim/court_truth_json.hpp"
#include "ballsight/sim/dataset_writer.hpp"
#include "ballsight/sim/ray_table.hpp"
#include "ballsight/sim/seeding.hpp"

namespace ballsight::sim {
namespace {

// Independent random streams of one data set seed.
enum Stream : std::uint64_t { kRigStream, kSceneStream, kBoardStream, kNoiseStream = 100 };

template <typename... Args>
std::string format_name(const char* pattern, Args... args) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, args...);
  return buffer;
}

void write_chessboards(const CourtDatasetOptions& options, const CourtRig& rig,
                       DatasetWriter& writer) {
  const std::uint64_t board_seed = derive_seed(options.seed, kBoardStream);
  ChessboardRenderOptions render_options;
  render_options.effects.noise_sigma = options.scenario.noise_sigma;
  std::vector<Json> cameras;
  for (size_t c = 0; c < rig.cameras.size(); ++c) {
    const PinholeCamera& camera = rig.cameras[c].camera;
    const std::uint64_t camera_seed = derive_seed(board_seed, c);
    const std::vector<Rigid3> poses = make_chessboard_poses(
        camera, options.board, options.chessboard_views, options.board_poses, camera_seed);
    const RayTable rays(camera);
    std::vector<ChessboardViewTruth> views;
    for (size_t v = 0; v < poses.size(); ++v) {
      const std::string name = format_name("cam%zu_board_%02zu.png", c, v);
      writer.png(name, render_chessboard(camera, rays, options.board, poses[v], render_options,
                                         derive_seed(camera_seed, kNoiseStream + v)));
      views.push_back(
          {name, poses[v], chessboard_corner_pixels(camera, options.board, poses[v]).value()});
    }
    cameras.push_back(chessboard_camera_json(camera, static_cast<int>(c), views));
  }
  writer.json("chessboards.json", chessboard_session_json(options.board, options.seed, cameras));
}

}  // namespace

void CourtDatasetOptions::validate() const {
  require(scenes >= 0 && scenes <= kMaxScenes, "scenes",
          "must be in [0, " + std::to_string(kMaxScenes) + "], got " + std::to_string(scenes));
  require(chessboard_views >= 0 && chessboard_views <= kMaxChessboardViews, "chessboards",
          "must be in [0, " + std::to_string(kMaxChessboardViews) + "], got " +
              std::to_string(chessboard_views));
  court.validate();
  rig.validate();
  scenario.validate();
  board.validate();
  board_poses.validate();
}

std::vector<std::string> write_court_dataset(const CourtDatasetOptions& options,
                                             const std::filesystem::path& out_dir) {
  options.validate();
  DatasetWriter writer(out_dir);
  const TennisCourtSpec& court = options.court;
  const CourtRig rig = make_court_rig(court, options.rig, derive_seed(options.seed, kRigStream));
  if (options.scenes > 0) {
    std::vector<CourtRenderer> renderers;
    for (const CourtCamera& camera : rig.cameras) renderers.emplace_back(camera, court);
    for (int k = 0; k < options.scenes; ++k) {
      const std::uint64_t scene_seed =
          derive_seed(derive_seed(options.seed, kSceneStream), static_cast<std::uint64_t>(k));
      const CourtScene scene = make_court_scene(court, options.scenario, scene_seed);
      std::vector<CourtRender> renders;
      std::vector<std::string> images;
      for (size_t c = 0; c < renderers.size(); ++c) {
        renders.push_back(renderers[c].render(scene, derive_seed(scene_seed, kNoiseStream + c)));
        images.push_back(format_name("court_%04d_cam%zu.png", k, c));
        writer.png(images.back(), renders.back().bgr);
      }
      const auto truth = court_scene_truth(rig, scene, renders);
      writer.json(format_name("court_%04d.json", k),
                  court_scene_json(rig, scene, truth, images, options.seed, k));
    }
  }
  if (options.chessboard_views > 0) write_chessboards(options, rig, writer);
  return std::move(writer).written();
}

}  // namespace ballsight::sim
