#pragma once
// What the court pipeline takes in: one frame per camera, each with when it was captured, so
// that the world model made from them, and every navigation update planned from that, carries
// the time of the frames (a robot reads its update's age from it).

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

namespace ballsight {

struct CameraFrame {
  std::size_t camera = 0;            // its index in the site's camera order
  cv::Mat image;                     // empty: the camera had no frame for this set
  std::int64_t capture_time_ns = 0;  // UTC: what updates carry to other processes
  std::uint64_t sequence = 0;        // frames its source delivered before this one
  /// When this process received it, on the steady clock: rates and ages within the process,
  /// which a step of the wall clock must not upset. Not set for a simulated or recorded scene.
  std::chrono::steady_clock::time_point received{};
};

struct FrameSet {
  std::vector<CameraFrame> cameras;  // one per camera, in camera order

  /// The oldest frame's capture time (UTC) of the cameras `used` (all when empty): how old a
  /// world model made from them is; 0 when none of them has a frame.
  std::int64_t capture_time_ns(const std::vector<bool>& used = {}) const;
  /// Whether some camera has a frame.
  bool any() const;
};

/// `images` (camera order; an empty Mat: no frame), all captured at `capture_time_ns` as their
/// sources' frame `sequence`: a simulated or recorded scene.
FrameSet frame_set_of(std::vector<cv::Mat> images, std::int64_t capture_time_ns,
                      std::uint64_t sequence = 0);

}  // namespace ballsight
