// Court simulator speed: one 1280x720 view of a scene with 40 balls on one core (target: at most
// 200 ms), the per-camera preparation it relies on, and one chessboard view.
// Run: build/bin/bench_sim_court

#include <benchmark/benchmark.h>

#include <opencv2/core.hpp>

#include "ballsight/sim/chessboard.hpp"
#include "ballsight/sim/chessboard_poses.hpp"
#include "ballsight/sim/court_renderer.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "ballsight/sim/court_scenario.hpp"

namespace {

using namespace ballsight::sim;

CourtRig bench_rig() {
  return make_court_rig(TennisCourtSpec{}, CourtRigOptions{}, 1);
}

void BM_RenderCourtView(benchmark::State& state) {
  cv::setNumThreads(1);
  const CourtRig rig = bench_rig();
  const CourtRenderer renderer(rig.cameras[0], rig.court);
  CourtScenarioOptions options;
  options.ball_count = 40;
  const CourtScene scene = make_court_scene(rig.court, options, 7);
  std::uint64_t noise_seed = 0;
  for (auto _ : state) benchmark::DoNotOptimize(renderer.render(scene, noise_seed++));
  state.SetItemsProcessed(state.iterations());
  state.SetLabel("1280x720, 40 tennis + 12 reference balls, robot, shadow, noise");
}
BENCHMARK(BM_RenderCourtView)->Unit(benchmark::kMillisecond);

void BM_PrepareCourtCamera(benchmark::State& state) {
  cv::setNumThreads(1);
  const CourtRig rig = bench_rig();
  for (auto _ : state) benchmark::DoNotOptimize(CourtRenderer(rig.cameras[0], rig.court));
  state.SetItemsProcessed(state.iterations());
  state.SetLabel("ray table + floor, once per camera");
}
BENCHMARK(BM_PrepareCourtCamera)->Unit(benchmark::kMillisecond);

void BM_RenderChessboardView(benchmark::State& state) {
  cv::setNumThreads(1);
  const ballsight::PinholeCamera camera = bench_rig().cameras[0].camera;
  const RayTable rays(camera);
  const ChessboardSpec board;
  const auto poses = make_chessboard_poses(camera, board, 1, {}, 1);
  const ChessboardRenderOptions options;
  for (auto _ : state) {
    benchmark::DoNotOptimize(render_chessboard(camera, rays, board, poses[0], options, 1));
  }
  state.SetItemsProcessed(state.iterations());
  state.SetLabel("1280x720, 4x4 supersampling");
}
BENCHMARK(BM_RenderChessboardView)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
