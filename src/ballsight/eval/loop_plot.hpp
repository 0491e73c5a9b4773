#pragma once
// Pictures of a closed-loop run (service/loop_truth.hpp): the court from above with the robot's
// true path, the published route at a few moments, and the balls coloured by when they were
// collected (grey with a red cross: never); and the per-update latency at the robot.

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "ballsight/service/loop_truth.hpp"

namespace ballsight {

cv::Mat draw_loop_map(const LoopTruth& truth, const std::string& title, int route_snapshots = 4);

/// Latency (ms) of each update at the robot against its sequence number.
cv::Mat draw_latency_chart(const std::vector<std::uint64_t>& seqs,
                           const std::vector<double>& latency_ms, const std::string& title);

}  // namespace ballsight
