#include "ballsight/pipeline/still_frame.hpp"

#include <exception>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <thread>

#include "ballsight/core/error.hpp"

namespace ballsight {

namespace {

// Opens the source and reads its still; throws std::runtime_error naming the source.
cv::Mat try_read_still(FrameSource& source, int live_frames) {
  source.open();
  std::optional<cv::Mat> first = source.read();
  if (!first) throw std::runtime_error("no frame from " + source.describe());
  if (!source.live() || live_frames == 1) return *first;
  cv::Mat sum;
  first->convertTo(sum, CV_64F);
  int frames = 1;
  for (; frames < live_frames; ++frames) {
    std::optional<cv::Mat> next;
    try {
      next = source.read();
    } catch (const std::exception&) {
      break;  // the stream ended or dropped: the frames so far are good
    }
    if (!next) break;
    if (next->size() != first->size() || next->type() != first->type())
      throw std::runtime_error("frame size changed while averaging " + source.describe());
    cv::accumulate(*next, sum);
  }
  cv::Mat mean;
  sum.convertTo(mean, first->type(), 1.0 / frames);
  return mean;
}

}  // namespace

void StillFrameOptions::validate() const {
  require(attempts >= 1 && attempts <= 100, "still frame attempts", "must be within [1, 100]");
  require(live_frames >= 1 && live_frames <= 1000, "still frame live_frames",
          "must be within [1, 1000]");
  backoff.validate();
}

cv::Mat read_still_frame(FrameSource& source, const StillFrameOptions& options) {
  options.validate();
  const int attempts = source.live() ? options.attempts : 1;
  std::string last_error;
  for (int attempt = 1; attempt <= attempts; ++attempt) {
    if (attempt > 1) std::this_thread::sleep_for(options.backoff.after(attempt - 1));
    try {
      return try_read_still(source, options.live_frames);
    } catch (const std::exception& e) {
      last_error = e.what();
    }
  }
  throw InputError(last_error + (attempts > 1
                                     ? " (gave up after " + std::to_string(attempts) + " attempts)"
                                     : ""));
}

}  // namespace ballsight
