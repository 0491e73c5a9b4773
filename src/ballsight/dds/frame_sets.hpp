#pragma once
// A court node's frame sets from its camera nodes' frames, which arrive one by one: frames whose
// capture times lie within `same_set` of each other form one set; a set goes to fusion once every
// live camera is in it, once each live camera missing from it has sent a later frame, or once
// `wait` passed since its first frame arrived. A camera is live while it was heard within
// `camera_timeout`: a camera node that stops leaves its court fusing the others, and one that
// comes back is waited for again from its next frame.

#include <chrono>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "ballsight/pipeline/court_pipeline.hpp"

namespace ballsight::dds {

struct FrameSetPolicy {
  std::chrono::nanoseconds same_set{std::chrono::milliseconds(40)};
  std::chrono::nanoseconds wait{std::chrono::milliseconds(250)};
  std::chrono::nanoseconds camera_timeout{std::chrono::seconds(2)};
};

/// One frame set as its camera nodes saw it: their detections, not the frames.
struct DetectionSet {
  std::int64_t capture_ns = 0;  // the first frame's capture time (UTC)
  CameraDetectionLists detections;
};

class FrameSetAssembler {
 public:
  using Clock = std::chrono::steady_clock;

  FrameSetAssembler(std::size_t cameras, const FrameSetPolicy& policy = {});

  /// Camera `camera`'s frame captured at `capture_ns` (nullopt detections: the node could not use
  /// it), arrived at `now`. A frame of a set already handed out is dropped (late).
  void add(std::size_t camera, std::int64_t capture_ns,
           std::optional<std::vector<PixelDetection>> detections, Clock::time_point now);
  /// The oldest set that is ready at `now`, oldest first; nullopt while none is.
  std::optional<DetectionSet> next(Clock::time_point now);
  /// Frames dropped because they came after their set was handed out.
  std::uint64_t late_frames() const { return late_; }

 private:
  struct Pending {
    CameraDetectionLists detections;
    std::vector<bool> present;
    Clock::time_point first_arrival;
  };
  bool live(std::size_t camera, Clock::time_point now) const;

  std::size_t cameras_;
  FrameSetPolicy policy_;
  std::map<std::int64_t, Pending> pending_;  // by capture time
  std::vector<std::optional<Clock::time_point>> heard_;
  std::vector<std::int64_t> newest_ns_;        // per camera, its newest frame's time
  std::optional<std::int64_t> handed_out_ns_;  // the newest set handed out
  std::uint64_t late_ = 0;
};

}  // namespace ballsight::dds
