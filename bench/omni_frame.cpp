// Whole-frame omni pipelines (segmentation, detection, conversion) on a simulated 640x480 frame:
// the omnivision paper's (YUV inRange, Algorithm 3 radial scan, px2cm table read as its robots)
// against ballsight's (colour-class table blob, silhouette rays through the ground map).
// Items processed = frames. One core: cv::setNumThreads(1).

#include <benchmark/benchmark.h>

#include <opencv2/core.hpp>

#include "ballsight/camera/iris_lut.hpp"
#include "ballsight/camera/rig_ground_map.hpp"
#include "ballsight/pipeline/omni_pipelines.hpp"
#include "ballsight/sim/omni_renderer.hpp"

namespace ballsight {
namespace {

struct Fixture {
  OmniRig rig;
  cv::Mat frame;
  Pose2D robot_cm{{400.0, 480.0}, 1.0};
  YuvRange ball_color = yuv_range_around(sim::OmniPalette{}.ball_bgr);
  GroundMap map;
  IrisLut px2cm;

  static Fixture make() {
    cv::setNumThreads(1);
    sim::OmniScene scene;
    scene.robot_pose = {{4.0, 4.8}, 1.0};
    scene.ball = sim::OmniBall{{4.0, 6.0}};
    scene.effects.noise_sigma = 3.0;
    const OmniRig rig(scene.rig);
    GroundMapInfo info;
    info.min_radius_px = 60.0;
    info.max_radius_px = 200.0;
    GroundMap map = ground_map_from_rig(rig, info);
    IrisLut table = iris_px2cm_from_ground_map(map);  // the same truth in the paper's layout
    return {rig,
            sim::render_omni_scene(scene).bgr,
            scene.robot_pose,
            yuv_range_around(scene.palette.ball_bgr),
            std::move(map),
            std::move(table)};
  }
};

const Fixture& fixture() {
  static const Fixture f = Fixture::make();
  return f;
}

void BM_OmniFrameSeedPipeline(benchmark::State& state) {
  const Fixture& f = fixture();
  const PaperOmniPipeline pipeline(f.ball_color, f.map.info().image_center_px,
                                   [&](double theta, double r) -> std::optional<double> {
                                     const auto d = iris_distance_cm(f.px2cm, theta, r);
                                     return d ? std::optional<double>(*d) : std::nullopt;
                                   });
  for (auto _ : state) benchmark::DoNotOptimize(pipeline.locate_cm(f.frame, f.robot_cm));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_OmniFrameSeedPipeline)->Unit(benchmark::kMicrosecond);

void BM_OmniFrameBallsight(benchmark::State& state) {
  const Fixture& f = fixture();
  const BallsightOmniPipeline pipeline(f.ball_color, f.map, BallOnFloor{});
  if (!pipeline.locate_cm(f.frame, f.robot_cm)) state.SkipWithError("no ball found");
  for (auto _ : state) benchmark::DoNotOptimize(pipeline.locate_cm(f.frame, f.robot_cm));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_OmniFrameBallsight)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace ballsight

BENCHMARK_MAIN();
