#include "ballsight/pipeline/frame_set.hpp"

#include <algorithm>
#include <optional>

namespace ballsight {

std::int64_t FrameSet::capture_time_ns(const std::vector<bool>& used) const {
  std::optional<std::int64_t> oldest;
  for (const CameraFrame& f : cameras) {
    if (f.image.empty() || (!used.empty() && !used.at(f.camera))) continue;
    oldest = std::min(oldest.value_or(f.capture_time_ns), f.capture_time_ns);
  }
  return oldest.value_or(0);
}

bool FrameSet::any() const {
  return std::any_of(cameras.begin(), cameras.end(),
                     [](const CameraFrame& f) { return !f.image.empty(); });
}

FrameSet frame_set_of(std::vector<cv::Mat> images, std::int64_t capture_time_ns,
                      std::uint64_t sequence) {
  FrameSet set;
  for (std::size_t k = 0; k < images.size(); ++k)
    set.cameras.push_back({k, std::move(images[k]), capture_time_ns, sequence, {}});
  return set;
}

}  // namespace ballsight
