#include "ballsight/dds/frame_sets.hpp"

#include <algorithm>
#include <limits>

namespace ballsight::dds {

FrameSetAssembler::FrameSetAssembler(std::size_t cameras, const FrameSetPolicy& policy)
    : cameras_(cameras),
      policy_(policy),
      heard_(cameras),
      newest_ns_(cameras, std::numeric_limits<std::int64_t>::min()) {}

bool FrameSetAssembler::live(std::size_t camera, Clock::time_point now) const {
  return heard_[camera] && now - *heard_[camera] <= policy_.camera_timeout;
}

void FrameSetAssembler::add(std::size_t camera, std::int64_t capture_ns,
                            std::optional<std::vector<PixelDetection>> detections,
                            Clock::time_point now) {
  if (camera >= cameras_) return;
  heard_[camera] = now;
  newest_ns_[camera] = std::max(newest_ns_[camera], capture_ns);
  const std::int64_t tolerance = policy_.same_set.count();
  if (handed_out_ns_ && capture_ns <= *handed_out_ns_ + tolerance) {
    ++late_;
    return;
  }
  // The set whose time is nearest, when within the tolerance; else a set of its own.
  auto it = pending_.lower_bound(capture_ns - tolerance);
  if (it == pending_.end() || it->first > capture_ns + tolerance) {
    it = pending_
             .emplace(capture_ns, Pending{CameraDetectionLists(cameras_),
                                          std::vector<bool>(cameras_, false), now})
             .first;
  }
  it->second.detections[camera] = std::move(detections);
  it->second.present[camera] = true;
}

std::optional<DetectionSet> FrameSetAssembler::next(Clock::time_point now) {
  if (pending_.empty()) return std::nullopt;
  auto oldest = pending_.begin();
  const Pending& set = oldest->second;
  bool ready = now - set.first_arrival >= policy_.wait;
  if (!ready) {
    ready = true;  // unless a live camera may still send a frame of it
    for (std::size_t c = 0; c < cameras_; ++c) {
      if (!set.present[c] && live(c, now) &&
          newest_ns_[c] <= oldest->first + policy_.same_set.count())
        ready = false;
    }
  }
  if (!ready) return std::nullopt;
  DetectionSet out{oldest->first, std::move(oldest->second.detections)};
  handed_out_ns_ = oldest->first;
  pending_.erase(oldest);
  return out;
}

}  // namespace ballsight::dds
