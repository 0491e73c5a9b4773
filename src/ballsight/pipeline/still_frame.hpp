#pragma once
// One still frame from any camera source, for calibration: the first image of a recorded source,
// or the mean of a few frames of a live one (a video device or a URL). A live source that cannot
// be opened or gives no frame is tried again a bounded number of times with back-off, then
// reported; a recorded one is read once (a missing file does not appear by waiting).

#include <opencv2/core.hpp>

#include "ballsight/pipeline/frame_source.hpp"

namespace ballsight {

struct StillFrameOptions {
  int attempts = 4;  // tries to open a live source and read its frames
  BackoffOptions backoff{std::chrono::milliseconds(500), std::chrono::milliseconds(4000), 2.0};
  int live_frames = 1;  // frames of a live source averaged into the still

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// The first frame of `source` if it is recorded, the mean of its next `live_frames` frames (8-bit,
/// fewer when the stream ends after the first) if it is live. Throws InputError naming the source
/// and the last error when it cannot be opened or yields no frame (after `attempts` tries, waiting
/// `backoff` between them, for a live source). Messages name the source ("cannot open video device
/// 97 (gave up after 4 attempts)").
cv::Mat read_still_frame(FrameSource& source, const StillFrameOptions& options = {});

}  // namespace ballsight
