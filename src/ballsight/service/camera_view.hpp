#pragma once
// What the service shows of one camera (the dashboard's camera panels, the court calibration
// page's stills): its last frame through the pipeline and what was detected in it.

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "ballsight/core/pixel_detection.hpp"

namespace ballsight {

struct CameraView {
  cv::Mat frame;  // 8-bit BGR as captured (shared: never written after capture)
  std::vector<PixelDetection> detections;
  std::uint64_t seq = 0;  // the update it went into
  std::int64_t capture_ns = 0;
};

}  // namespace ballsight
