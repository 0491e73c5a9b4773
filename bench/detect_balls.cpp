// `detect balls` (the shipped settings) on 640x480 photos: each real labelled photo of at most
// 640x480
// (../shared/data/real/tennis) padded to 640x480 with its own edge (real_<file>; skipped when the
// data is absent), a drawn hard court with six balls of 3 to 60 px radius (drawn_court), and the
// same court with a white line under a hall's warm lamp (drawn_court_warm_lamp: the colour table is
// corrected for the cast, detect/colour_cast.hpp); and the court simulator's frame of 1920x1080
// (sim_court_1080p), and the four cameras' frames of that scene as one frame set searched on
// both cores (sim_court_4x1080p_frame_set: issue 42's four cameras at 10 Hz). The targets (issues
// 12 and 42) are <= 3 ms per 640x480 photo and <= 10 ms per 1920x1080 frame on one core. The
// argument is PhotoBallOptions::bands: 1 searches the image in one band on one thread, 0 in one
// band per OpenCV thread; read the wall time (with
// --benchmark_repetitions, the median and the fastest repetition, "min").

#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <opencv2/imgproc.hpp>
#include <thread>
#include <vector>

#include "ballsight/camera/image_file.hpp"
#include "ballsight/detect/ball_labels.hpp"
#include "ballsight/detect/photo_ball_fit.hpp"
#include "ballsight/detect/photo_balls.hpp"
#include "ballsight/eval/court_eval_scenes.hpp"

namespace ballsight {
namespace {

namespace fs = std::filesystem;

void detect(benchmark::State& state, const cv::Mat& image) {
  PhotoBallOptions options = shipped_photo_ball_options();
  options.bands = static_cast<int>(state.range(0));
  PhotoBallDetector detector(options);
  std::size_t balls = 0;
  for (auto _ : state) {
    const std::vector<PhotoBall> found = detector.detect(image);
    balls = found.size();
    benchmark::DoNotOptimize(found.data());
  }
  state.counters["balls"] = static_cast<double>(balls);
}

cv::Mat drawn_court(bool warm_lamp) {
  cv::Mat image(480, 640, CV_8UC3, cv::Scalar(150, 120, 95));
  if (warm_lamp) cv::line(image, {0, 400}, {639, 420}, cv::Scalar::all(215), 3);
  cv::Mat noise(image.size(), CV_8UC3);
  cv::randn(noise, cv::Scalar::all(0), cv::Scalar::all(4));
  cv::add(image, noise, image, cv::noArray(), CV_8UC3);
  const int radii[] = {3, 6, 12, 25, 40, 60};
  for (int i = 0; i < 6; ++i)
    cv::circle(image, {60 + 100 * i, 120 + 50 * i}, radii[i], cv::Scalar(45, 245, 220), -1,
               cv::LINE_AA);
  if (warm_lamp) cv::multiply(image, cv::Scalar(0.8, 1.0, 1.12), image);
  return image;
}

// The four cameras' frames of the court simulator's first scene (seed 1) at 1920x1080: the
// court, its lines, the net, the tennis balls, reference balls and the robot.
std::vector<cv::Mat> simulated_court_1080p() {
  sim::CourtRigOptions rig;
  rig.width = 1920;
  rig.height = 1080;
  const CourtEvalScenes scenes(sim::TennisCourtSpec{}, rig, 1);
  std::vector<cv::Mat> frames;
  for (const sim::CourtRender& render : scenes.render(sim::CourtScenarioOptions{}, 0).renders)
    frames.push_back(render.bgr);
  return frames;
}

// A frame set of four cameras, each camera's frame searched by its own detector in one band, two
// cameras on each of two threads (one per core): the wall time of a frame set.
void detect_frame_set(benchmark::State& state, const std::vector<cv::Mat>& frames) {
  PhotoBallOptions options = shipped_photo_ball_options();
  options.bands = 1;
  std::vector<PhotoBallDetector> detectors(frames.size(), PhotoBallDetector(options));
  std::vector<std::size_t> balls(frames.size());
  const auto cameras = [&](std::size_t first) {
    for (std::size_t k = first; k < frames.size(); k += 2)
      balls[k] = detectors[k].detect(frames[k]).size();
  };
  for (auto _ : state) {
    std::thread other(cameras, 1);
    cameras(0);
    other.join();
  }
  std::size_t total = 0;
  for (const std::size_t n : balls) total += n;
  state.counters["balls"] = static_cast<double>(total);
}

void register_benchmarks() {
  const auto both = [](benchmark::internal::Benchmark* b) {
    b->ArgName("bands")->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();
    // With --benchmark_repetitions: the fastest repetition too, the photo's cost with the least
    // interference from a shared machine.
    b->ComputeStatistics(
        "min", [](const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); });
  };
  both(benchmark::RegisterBenchmark("drawn_court", detect, drawn_court(false)));
  both(benchmark::RegisterBenchmark("drawn_court_warm_lamp", detect, drawn_court(true)));
  const std::vector<cv::Mat> frames = simulated_court_1080p();
  both(benchmark::RegisterBenchmark("sim_court_1080p", detect, frames[0]));
  benchmark::RegisterBenchmark("sim_court_4x1080p_frame_set", detect_frame_set, frames)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
  // Every real labelled photo of at most 640x480, padded to 640x480.
  for (const LabelledSource& source :
       read_labelled_sources(fs::path(BALLSIGHT_SHARED_DATA_DIR) / "real" / "tennis")) {
    for (const LabelledImage& image : source.images) {
      const cv::Mat real = read_image_bgr(source.images_dir / image.file);
      if (real.cols > 640 || real.rows > 480) continue;
      cv::Mat padded;
      const int rows = (480 - real.rows) / 2, cols = (640 - real.cols) / 2;
      cv::copyMakeBorder(real, padded, rows, 480 - real.rows - rows, cols, 640 - real.cols - cols,
                         cv::BORDER_REPLICATE);
      both(benchmark::RegisterBenchmark(("real_" + image.file).c_str(), detect, padded));
    }
  }
}

}  // namespace
}  // namespace ballsight

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  ballsight::register_benchmarks();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
