#pragma once
// What the DDS node commands (camera-node, court-node, omni-node) share: their options (the ROS 2
// namespace, the DDS domain, loopback only, how long to run) and their frames' pace.

#include <CLI/CLI.hpp>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "ballsight/dds/domain.hpp"
#include "ballsight/pipeline/frame_source.hpp"

namespace ballsight::app {

struct DdsArgs {
  dds::DomainOptions domain;
  int domain_id = -1;  // -1: ROS_DOMAIN_ID or 0
  double duration_s = 0.0;

  dds::DomainOptions domain_options() const;
};

/// --namespace, --domain, --loopback; `topics` names what the namespace holds.
std::vector<CLI::Option*> add_domain_options(CLI::App& command, DdsArgs& args,
                                             const std::string& topics);
/// The same and --duration.
void add_dds_options(CLI::App& command, DdsArgs& args, const std::string& topics);
/// Throws InputError naming the option at fault.
void validate(const DdsArgs& args);
/// "/" or "/NS/": what the node's topic names begin with.
std::string topic_prefix(const DdsArgs& args);

/// What a node does with a frame: `index` its camera's frame counter, `capture_ns` (UTC) when it
/// was captured.
using FramePublisher =
    std::function<void(const cv::Mat& frame, std::uint64_t index, std::int64_t capture_ns)>;

/// Simulated frames at wall-clock ticks of `rate_hz` until `stop`: tick k's frame is rendered
/// (`render(k)`) just ahead of it and published at the tick, stamped k / rate_hz, as a camera
/// delivers a frame when it is captured; nodes of one simulated court render the same tick alike.
void publish_ticks(double rate_hz, const std::atomic<bool>& stop,
                   const std::function<cv::Mat(std::uint64_t tick)>& render,
                   const FramePublisher& publish);
/// A real camera's frames as they come until `stop` (problems told on stderr as `program`'s).
void publish_captured(const std::string& program, const std::string& camera,
                      std::unique_ptr<FrameSource> source, const std::atomic<bool>& stop,
                      const FramePublisher& publish);

}  // namespace ballsight::app
