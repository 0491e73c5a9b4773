// What recording a run costs (docs/recording.md): the recorder's work for one navigation update
// with the frames and detections of four 1920x1080 cameras (JPEG at quality 85, JSON, base64,
// the chunk's compression and the write), beside the court pipeline's work for the same frame
// set, and an update without frames. One thread, as the recorder has. Run:
// build/bin/bench_record (items = updates).

#include <benchmark/benchmark.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "ballsight/detect/court_detector.hpp"
#include "ballsight/service/run_file.hpp"
#include "court_frames.hpp"

namespace {

using namespace ballsight;

/// The update of the benchmark's frame set through ballsight's pipeline, and its camera views.
struct Recorded {
  NavigationUpdate update;
  std::vector<CameraView> views;
};

const Recorded& recorded() {
  static const Recorded r = [] {
    const bench::Setup& s = bench::setup();
    Recorded out;
    const auto pipeline = make_ballsight_pipeline(s.cameras, s.options);
    const FrameSetResult result = pipeline->process(s.frames);
    out.update.world = result.world;
    for (std::size_t k = 0; k < s.cameras.size(); ++k) {
      CameraView view{s.frames.cameras[k].image, {}, 1, 0};
      if (k < result.detections.size() && result.detections[k]) {
        view.detections = *result.detections[k];
      }
      out.views.push_back(std::move(view));
    }
    return out;
  }();
  return r;
}

void record(benchmark::State& state, mcap::Compression compression, bool frames,
            FrameEncoding encoding = FrameEncoding::jpeg) {
  const bench::Setup& s = bench::setup();
  RunDescription run;
  run.service_id = "bench";
  for (const SiteCamera& camera : s.site.cameras) run.camera_names.push_back(camera.name);
  run.setup.site = s.site;
  run.compression = compression;
  run.frames = encoding;
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "ballsight_bench_record.mcap";
  NavigationUpdate update = recorded().update;
  const std::vector<CameraView> none;
  std::uint64_t bytes = 0;
  {
    RunFile file(path, run, 1);
    for (auto _ : state) {
      ++update.seq;
      file.write_update(update, frames ? recorded().views : none);
    }
    file.close();
    bytes = file.size();
  }
  std::filesystem::remove(path);
  state.SetItemsProcessed(state.iterations());
  state.counters["bytes_per_update"] =
      static_cast<double>(bytes) /
      static_cast<double>(std::max<benchmark::IterationCount>(1, state.iterations()));
}

void BM_RecordUpdateWithFrames(benchmark::State& state) {
  const auto compression = static_cast<mcap::Compression>(state.range(0));
  const bool png = state.range(1) != 0;
  record(state, compression, true, png ? FrameEncoding::png : FrameEncoding::jpeg);
  state.SetLabel(std::string(png ? "4 x 1920x1080 PNG (zlib 1)" : "4 x 1920x1080 JPEG q85") +
                 " + update, " +
                 (compression == mcap::Compression::none ? std::string("no compression")
                                                         : mcap::compression_name(compression)));
}
BENCHMARK(BM_RecordUpdateWithFrames)
    ->Args({static_cast<int>(mcap::Compression::zstd), 0})
    ->Args({static_cast<int>(mcap::Compression::lz4), 0})
    ->Args({static_cast<int>(mcap::Compression::none), 0})
    ->Args({static_cast<int>(mcap::Compression::zstd), 1})
    ->Unit(benchmark::kMillisecond);

void BM_RecordUpdateOnly(benchmark::State& state) {
  record(state, mcap::Compression::zstd, false);
  state.SetLabel("the update alone (--record-every 0), zstd");
}
BENCHMARK(BM_RecordUpdateOnly)->Unit(benchmark::kMicrosecond);

void BM_RecordJpegOneFrame(benchmark::State& state) {
  const cv::Mat& frame = bench::setup().frames.cameras[0].image;
  const std::vector<int> quality{cv::IMWRITE_JPEG_QUALITY, 85};
  std::vector<std::uint8_t> bytes;
  for (auto _ : state) cv::imencode(".jpg", frame, bytes, quality);
  state.SetItemsProcessed(state.iterations());
  state.SetLabel("1920x1080, quality 85");
}
BENCHMARK(BM_RecordJpegOneFrame)->Unit(benchmark::kMillisecond);

// The same frame set through ballsight's court pipeline: what a service does for it without
// recording.
void BM_RecordBesidePipeline(benchmark::State& state) {
  const bench::Setup& s = bench::setup();
  const auto pipeline = make_ballsight_pipeline(s.cameras, s.options);
  for (auto _ : state) benchmark::DoNotOptimize(pipeline->process(s.frames));
  state.SetItemsProcessed(state.iterations());
  state.SetLabel("4 x 1920x1080 -> world model, ballsight (CPU of the whole process)");
}
BENCHMARK(BM_RecordBesidePipeline)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
