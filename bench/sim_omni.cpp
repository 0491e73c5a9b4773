// Omni simulator rendering cost: target at most 50 ms per 640x480 frame on one core (issue 2).
// Run: build/bench/bench_sim_omni

#include <benchmark/benchmark.h>

#include <opencv2/core.hpp>

#include "ballsight/sim/omni_marker_layout.hpp"
#include "ballsight/sim/omni_renderer.hpp"
#include "ballsight/sim/omni_scenario.hpp"

namespace {

using namespace ballsight::sim;

// The scenario's frames in turn: frame 0 is the calibration frame with 324 markers, the others
// show a ball; with `effects` the frames get noise, blur and a brightness change.
void render_scenario(benchmark::State& state, const ImageEffects& effects) {
  cv::setNumThreads(1);
  OmniScenarioOptions options;
  options.frames = 8;
  options.effects = effects;
  const OmniScenario scenario = make_omni_scenario(options);
  const OmniRenderer renderer(scenario.rig);
  std::size_t i = 0;
  for (auto _ : state) {
    const OmniFrame frame = renderer.render(scenario.scenes[i++ % scenario.scenes.size()]);
    benchmark::DoNotOptimize(frame.bgr.data);
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_RenderOmniFrame(benchmark::State& state) {
  render_scenario(state, {});
}
BENCHMARK(BM_RenderOmniFrame)->Unit(benchmark::kMillisecond);

void BM_RenderOmniFrameWithEffects(benchmark::State& state) {
  render_scenario(state, {1.2, 1.0, 3.0});
}
BENCHMARK(BM_RenderOmniFrameWithEffects)->Unit(benchmark::kMillisecond);

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
