#include "node_options.hpp"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <thread>

#include "ballsight/core/error.hpp"
#include "ballsight/core/utc_clock.hpp"
#include "ballsight/pipeline/capture.hpp"

namespace ballsight::app {

dds::DomainOptions DdsArgs::domain_options() const {
  dds::DomainOptions options = domain;
  if (domain_id >= 0) options.domain = domain_id;
  return options;
}

std::vector<CLI::Option*> add_domain_options(CLI::App& command, DdsArgs& args,
                                             const std::string& topics) {
  return {command.add_option("--namespace", args.domain.ns,
                             "ROS 2 namespace of the " + topics + " (court1: /court1/...)"),
          command.add_option("--domain", args.domain_id,
                             "DDS domain id (default: ROS_DOMAIN_ID, else 0)"),
          command.add_flag(
              "--loopback", args.domain.loopback,
              "DDS on this machine only (127.0.0.1, no multicast; as ROS 2's LOCALHOST range)")};
}

void add_dds_options(CLI::App& command, DdsArgs& args, const std::string& topics) {
  add_domain_options(command, args, topics);
  command
      .add_option("--duration", args.duration_s, "Stop after this many seconds (0: on a signal)")
      ->capture_default_str();
}

void validate(const DdsArgs& args) {
  require(args.duration_s >= 0.0, "--duration", "must not be negative");
  args.domain_options().validate();
}

std::string topic_prefix(const DdsArgs& args) {
  return "/" + (args.domain.ns.empty() ? "" : args.domain.ns + "/");
}

void publish_ticks(double rate_hz, const std::atomic<bool>& stop,
                   const std::function<cv::Mat(std::uint64_t tick)>& render,
                   const FramePublisher& publish) {
  const auto period_ns = static_cast<std::int64_t>(1e9 / rate_hz);
  const auto sleep_until_ns = [&stop](std::int64_t utc_ns) {  // a tenth of a second at a time
    for (std::int64_t left = utc_ns - utc_now_ns(); left > 0 && !stop; left = utc_ns - utc_now_ns())
      std::this_thread::sleep_for(
          std::chrono::nanoseconds(std::min<std::int64_t>(left, 100'000'000)));
  };
  // Rendered just ahead of its tick (twice the last rendering's time and 2 ms, at most half a
  // period): clear of the work on the previous tick on a shared machine, and the machine awake at
  // the tick as it is for a court rendered and detected in one process.
  std::int64_t tick = utc_now_ns() / period_ns + 1;
  std::int64_t render_ns = period_ns / 4;
  while (!stop) {
    sleep_until_ns(tick * period_ns - std::min(period_ns / 2, 2 * render_ns + 2'000'000));
    const std::int64_t started_ns = utc_now_ns();
    const cv::Mat frame = render(static_cast<std::uint64_t>(tick));
    render_ns = utc_now_ns() - started_ns;
    sleep_until_ns(tick * period_ns);
    if (stop) break;
    publish(frame, static_cast<std::uint64_t>(tick), tick * period_ns);
    tick = std::max(tick + 1, utc_now_ns() / period_ns + 1);
  }
}

void publish_captured(const std::string& program, const std::string& camera,
                      std::unique_ptr<FrameSource> source, const std::atomic<bool>& stop,
                      const FramePublisher& publish) {
  CameraCapture capture(
      camera, std::move(source), CaptureOptions{},
      [&program](const std::string& message) { std::cerr << program << ": " << message << "\n"; });
  capture.start();
  while (!stop) {
    if (std::optional<Frame> frame = capture.frames().pop(std::chrono::milliseconds(100))) {
      publish(frame->image, frame->sequence, utc_ns_of(frame->timestamp));
    }
  }
}

}  // namespace ballsight::app
