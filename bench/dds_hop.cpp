// One DDS hop on loopback between two processes, as camera node -> court node and court node ->
// subscriber cross it (issue 14): a ballsight_msgs/CameraDetections sent to an echo process
// (this program started again with --echo) and back; the counters are half the round trip, in
// milliseconds, over every message of the run.
// - BM_DetectionsHop/N: a camera's detections of N balls, each with a 10 x 10 coverage patch
//   (N = 30: about 15 kB, near the 13 kB a camera of the simulated court writes with 30 balls).
// Run: build/bin/bench_dds_hop

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <thread>

#include "ballsight/core/child_process.hpp"
#include "ballsight/dds/detection_messages.hpp"
#include "ballsight/dds/topic_io.hpp"
#include "ballsight/eval/court_metrics.hpp"
#include "ballsight/service/navigation_hub.hpp"

namespace {

using namespace ballsight;
using namespace std::chrono_literals;

constexpr std::uint64_t kStop = ~std::uint64_t{0};  // the frame number that ends the echo

dds::DomainOptions bench_domain(int domain, const std::string& ns) {
  dds::DomainOptions options;
  options.domain = domain;
  options.loopback = true;
  options.ns = ns;
  return options;
}

// The echo process: every "ping" written back on "pong" until the stop frame.
int run_echo(int domain, const std::string& ns) {
  const dds::Participant participant(bench_domain(domain, ns));
  dds::Reader<dds::CameraDetectionsMsg> ping(participant, "ping");
  dds::Writer<dds::CameraDetectionsMsg> pong(participant, "pong");
  bool stop = false;
  const auto idle_until = [] { return std::chrono::steady_clock::now() + 60s; };
  auto until = idle_until();
  while (!stop && std::chrono::steady_clock::now() < until) {
    if (!ping.wait(100ms)) continue;
    ping.take([&](const dds::CameraDetectionsMsg& m) {
      stop = stop || m.frame == kStop;
      pong.write(m);
    });
    until = idle_until();
  }
  return 0;
}

dds::CameraFrameDetections detections(int balls) {
  dds::CameraFrameDetections frame{"camera 0", 0, 0, "", {}, {}};
  for (int k = 0; k < balls; ++k) {
    PixelDetection d;
    d.center_px = Vec2(40.0 * k, 300.0);
    d.radius_px = 8.0;
    d.area_px = 201.0;
    d.patch = {40 * k - 5, 295, 10, 10, std::vector<float>(100, 0.5f), k};
    frame.detections.push_back(d);
    frame.ground.push_back(Vec3(0.5 * k, 3.0, 0.0335));
  }
  return frame;
}

void BM_DetectionsHop(benchmark::State& state) {
  std::random_device random;
  const int domain = 100 + static_cast<int>(random() % 130);
  const std::string ns = "bench" + random_hex(8);
  const std::filesystem::path log = std::filesystem::temp_directory_path() / (ns + ".log");
  ChildProcess echo(own_executable(), {"--echo", std::to_string(domain), ns}, log);
  const dds::Participant participant(bench_domain(domain, ns));
  dds::Writer<dds::CameraDetectionsMsg> ping(participant, "ping");
  dds::Reader<dds::CameraDetectionsMsg> pong(participant, "pong");
  for (int k = 0; k < 500 && (ping.matched_readers() == 0 || pong.matched_writers() == 0); ++k)
    std::this_thread::sleep_for(10ms);
  if (ping.matched_readers() == 0 || pong.matched_writers() == 0) {
    state.SkipWithError("the echo process did not match within 5 s");
    return;
  }
  dds::CameraFrameDetections frame = detections(static_cast<int>(state.range(0)));
  std::vector<double> one_way_ms;
  for (auto _ : state) {
    ++frame.frame;
    dds::MessageArena arena;
    const dds::CameraDetectionsMsg message = dds::camera_detections_message(frame, arena);
    const auto sent = std::chrono::steady_clock::now();
    ping.write(message);
    bool back = false;
    while (!back) {
      if (!pong.wait(2s)) {
        state.SkipWithError("no echo within 2 s");
        return;
      }
      pong.take([&](const dds::CameraDetectionsMsg& m) { back = back || m.frame == frame.frame; });
    }
    one_way_ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - sent).count() /
        2.0);
  }
  // Its size on the wire: one more message, taken back as bytes.
  ++frame.frame;
  dds::MessageArena arena;
  ping.write(dds::camera_detections_message(frame, arena));
  std::size_t bytes = 0;
  for (int k = 0; k < 20 && bytes == 0; ++k)
    if (pong.wait(100ms))
      for (const std::vector<std::uint8_t>& cdr : pong.take_serialized()) bytes = cdr.size();
  frame.frame = kStop;
  ping.write(dds::camera_detections_message(frame, arena));
  echo.wait(5s);
  std::filesystem::remove(log);
  state.counters["p50_ms"] = quantile(one_way_ms, 0.5);
  state.counters["p99_ms"] = quantile(one_way_ms, 0.99);
  state.counters["max_ms"] = quantile(one_way_ms, 1.0);
  state.counters["bytes"] = static_cast<double>(bytes);
}
BENCHMARK(BM_DetectionsHop)->Arg(3)->Arg(30)->Arg(60)->Iterations(2000)->UseRealTime();

}  // namespace

int main(int argc, char** argv) {
  if (argc == 4 && std::strcmp(argv[1], "--echo") == 0)
    return run_echo(std::stoi(argv[2]), argv[3]);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
