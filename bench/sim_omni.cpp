// Omni simulator rendering cost: target at most 50 ms per 640x480 frame on one core (issue 2).
// Run: build/bench/bench_sim_omni   (figures in docs/sim-omni.md)

#include <benchmark/benchmark.h>

#include <opencv2/core.hpp>

#include "ballsight/sim/omni_renderer.hpp"
#include "ballsight/sim/omni_scenario.hpp"

namespace {

using namespace ballsight::sim;

// Renders frames of a default scenario in turn, one core. Frame 0 of a scenario is the
// calibration frame (324 markers); `calibration` picks it, otherwise the ball frames 1..7.
void render_frames(benchmark::State& state, bool calibration, const ImageEffects& effects) {
  cv::setNumThreads(1);
  OmniScenarioOptions options;
  options.frames = 8;
  options.effects = effects;
  const OmniScenario scenario = make_omni_scenario(options);
  const OmniRenderer renderer(scenario.rig);
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t frame = calibration ? 0 : 1 + i++ % (scenario.scenes.size() - 1);
    const OmniFrame rendered = renderer.render(scenario.scenes[frame]);
    benchmark::DoNotOptimize(rendered.bgr.data);
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_RenderOmniFrame(benchmark::State& state) {
  render_frames(state, false, {});
}
BENCHMARK(BM_RenderOmniFrame)->Unit(benchmark::kMillisecond);

void BM_RenderOmniFrameWithEffects(benchmark::State& state) {
  render_frames(state, false, {1.2, 1.0, 3.0});  // brightness 1.2, blur 1 px, noise 3 levels
}
BENCHMARK(BM_RenderOmniFrameWithEffects)->Unit(benchmark::kMillisecond);

void BM_RenderOmniCalibrationFrame(benchmark::State& state) {
  render_frames(state, true, {});
}
BENCHMARK(BM_RenderOmniCalibrationFrame)->Unit(benchmark::kMillisecond);

// The once-per-rig cost: every pixel's ray and floor hit.
void BM_PrepareOmniRenderer(benchmark::State& state) {
  for (auto _ : state) {
    const OmniRenderer renderer{ballsight::OmniRigParams{}};
    benchmark::DoNotOptimize(&renderer);
  }
}
BENCHMARK(BM_PrepareOmniRenderer)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
