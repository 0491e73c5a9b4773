// Court vision speed: four 1920x1080 frames (the report's IP cameras, one per corner camera) ->
// world model, for the report's pipeline (HSV, median filter, contours, z = 0, fixed-distance
// merge) and ballsight's (the targets: at most 15 ms and at least 4x faster than the report's in
// the same run), and the stages of ballsight's alone. Both run one std::async task per camera (the
// report's section 7.7); OpenCV's own threads are off so that the cameras share the cores the same
// way in both. Run: build/bin/bench_court_pipeline (items processed = frame sets or frames; CPU
// time is the whole process's, wall time is real time).

#include "ballsight/pipeline/court_pipeline.hpp"

#include <benchmark/benchmark.h>

#include <opencv2/core.hpp>

#include "ballsight/detect/court_detector.hpp"
#include "ballsight/world/court_world.hpp"
#include "court_frames.hpp"

namespace {

using namespace ballsight;
using bench::render_setup;
using bench::Setup;
using bench::setup;

void run_frame_sets(benchmark::State& state, CourtPipeline& pipeline, const Setup& s = setup()) {
  for (auto _ : state) benchmark::DoNotOptimize(pipeline.process(s.frames));
  state.SetItemsProcessed(state.iterations());
}

void BM_CourtFrameSetSeedPipeline(benchmark::State& state) {
  const auto pipeline = make_seed_pipeline(setup().cameras);
  run_frame_sets(state, *pipeline);
  state.SetLabel("4 x 1920x1080 -> world model, the report's pipeline");
}
BENCHMARK(BM_CourtFrameSetSeedPipeline)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

void BM_CourtFrameSetBallsight(benchmark::State& state) {
  const auto pipeline = make_ballsight_pipeline(setup().cameras, setup().options);
  run_frame_sets(state, *pipeline);
  state.SetLabel("4 x 1920x1080 -> world model, ballsight");
}
BENCHMARK(BM_CourtFrameSetBallsight)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

// A person and a bag on the court, and the pipeline given each camera's empty-court view: the
// obstacles found as well (detect/court_foreground.hpp, world/floor_obstacles.hpp).
void BM_CourtFrameSetBallsightObstacles(benchmark::State& state) {
  static const Setup s = render_setup(sim::CourtSurface::green, true);
  const auto pipeline = make_ballsight_pipeline(s.cameras, s.options);
  run_frame_sets(state, *pipeline, s);
  state.SetLabel("4 x 1920x1080 with a person and a bag -> world model and obstacles, ballsight");
}
BENCHMARK(BM_CourtFrameSetBallsightObstacles)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

// A blue court (hue about 209 deg), whose robot wears a violet back marker: a blue one (224 deg)
// would make the court grow into one blob of its colour on every frame (left out by its
// evidence, at twice the cost: docs/RESULTS.md).
void BM_CourtFrameSetBallsightBlueCourt(benchmark::State& state) {
  static const Setup s = render_setup(sim::CourtSurface::blue);
  const auto pipeline = make_ballsight_pipeline(s.cameras, s.options);
  run_frame_sets(state, *pipeline, s);
  state.SetLabel("4 x 1920x1080 on a blue court -> world model, ballsight");
}
BENCHMARK(BM_CourtFrameSetBallsightBlueCourt)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

// Stages of ballsight's pipeline, single-threaded.
void BM_CourtDetectorOneFrame(benchmark::State& state) {
  const Setup& s = setup();
  CourtDetector detector(s.cameras[0]);
  for (auto _ : state) benchmark::DoNotOptimize(detector.detect(s.frames.cameras[0].image));
  state.SetItemsProcessed(state.iterations());
  state.SetLabel("1920x1080, camera 0");
}
BENCHMARK(BM_CourtDetectorOneFrame)->Unit(benchmark::kMillisecond);

void BM_CourtWorldModel(benchmark::State& state) {
  const Setup& s = setup();
  std::vector<std::optional<std::vector<PixelDetection>>> detections;
  for (size_t c = 0; c < s.cameras.size(); ++c)
    detections.push_back(CourtDetector(s.cameras[c]).detect(s.frames.cameras[c].image));
  const CourtWorldOptions options;
  for (auto _ : state) benchmark::DoNotOptimize(build_world_model(s.cameras, detections, options));
  state.SetItemsProcessed(state.iterations());
  state.SetLabel("4 cameras' detections -> world model");
}
BENCHMARK(BM_CourtWorldModel)->Unit(benchmark::kMillisecond);

void BM_SeedDetectorOneFrame(benchmark::State& state) {
  const Setup& s = setup();
  const SeedDetectorOptions options;
  for (auto _ : state) benchmark::DoNotOptimize(detect_seed(s.frames.cameras[0].image, options));
  state.SetItemsProcessed(state.iterations());
  state.SetLabel("1920x1080, camera 0");
}
BENCHMARK(BM_SeedDetectorOneFrame)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
