// Court calibration speed on one core: finding the reference balls in a 1280x720 view, the
// camera's pose from those blobs (P3P hypotheses + refinement), one chessboard view's corners
// and the intrinsic calibration from 15 views (with the k3 cross-validation).
// Run: build/bin/bench_court_calibration

#include "ballsight/pipeline/court_calibration.hpp"

#include <benchmark/benchmark.h>

#include <opencv2/core.hpp>

#include "ballsight/calib/chessboard_corners.hpp"
#include "ballsight/calib/intrinsics.hpp"
#include "ballsight/calib/reference_pose.hpp"
#include "ballsight/detect/color_blobs.hpp"
#include "ballsight/sim/chessboard.hpp"
#include "ballsight/sim/chessboard_poses.hpp"
#include "ballsight/sim/court_renderer.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "ballsight/sim/court_scenario.hpp"

namespace {

using namespace ballsight;

struct CourtView {
  sim::CourtRig rig = sim::make_court_rig({}, {}, 1);
  cv::Mat image = sim::CourtRenderer(rig.cameras[0], rig.court)
                      .render(sim::make_court_scene(rig.court, {}, 1), 1)
                      .bgr;
};

const CourtView& court_view() {
  static const CourtView view;
  return view;
}

void BM_FindReferenceBlobs(benchmark::State& state) {
  cv::setNumThreads(1);
  const cv::Mat& image = court_view().image;
  for (auto _ : state) benchmark::DoNotOptimize(find_color_blobs(image, {}));
  state.SetLabel("1280x720 court view, orange blobs");
}
BENCHMARK(BM_FindReferenceBlobs)->Unit(benchmark::kMillisecond);

void BM_ReferencePose(benchmark::State& state) {
  cv::setNumThreads(1);
  const CourtView& view = court_view();
  std::vector<Vec2> candidates;
  for (const ColorBlob& blob : find_color_blobs(view.image, {})) {
    candidates.push_back(blob.centroid_px);
  }
  std::vector<ReferencePoint> references;
  for (const Vec3& p : sim::reference_ball_positions(view.rig.court)) {
    references.push_back({"ref", p});
  }
  const Vec3 hint(18.25, 9.25, 5.0);
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        estimate_reference_pose(view.rig.cameras[0].camera, references, candidates, hint));
  }
  state.SetLabel(std::to_string(candidates.size()) + " blobs, 12 references");
}
BENCHMARK(BM_ReferencePose)->Unit(benchmark::kMillisecond);

struct ChessboardSession {
  PinholeCamera camera = court_view().rig.cameras[0].camera;
  sim::ChessboardSpec board;
  ChessboardPattern pattern{board.inner_cols, board.inner_rows, board.square_m};
  std::vector<cv::Mat> images;
  std::vector<ChessboardView> views;

  ChessboardSession() {
    const sim::RayTable rays(camera);
    sim::ChessboardRenderOptions options;
    options.effects.noise_sigma = 2.0;
    const auto poses = sim::make_chessboard_poses(camera, board, 15, {}, 3);
    for (std::size_t v = 0; v < poses.size(); ++v) {
      images.push_back(sim::render_chessboard(camera, rays, board, poses[v], options, v));
      if (auto corners = find_chessboard_corners(images.back(), pattern)) {
        views.push_back({std::to_string(v), *corners});
      }
    }
  }
};

const ChessboardSession& chessboard_session() {
  static const ChessboardSession session;
  return session;
}

void BM_FindChessboardCorners(benchmark::State& state) {
  cv::setNumThreads(1);
  const ChessboardSession& s = chessboard_session();
  std::size_t v = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(find_chessboard_corners(s.images[v++ % s.images.size()], s.pattern));
  }
  state.SetLabel("1280x720, 9x6 inner corners, sub-pixel");
}
BENCHMARK(BM_FindChessboardCorners)->Unit(benchmark::kMillisecond);

void BM_CalibrateIntrinsics(benchmark::State& state) {
  cv::setNumThreads(1);
  const ChessboardSession& s = chessboard_session();
  for (auto _ : state) {
    benchmark::DoNotOptimize(calibrate_intrinsics(s.views, s.pattern, {1280, 720}));
  }
  state.SetLabel(std::to_string(s.views.size()) + " views, k3 cross-validation (4 folds)");
}
BENCHMARK(BM_CalibrateIntrinsics)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
