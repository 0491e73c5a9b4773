#include "ballsight/pipeline/capture.hpp"

#include <algorithm>
#include <cstdio>
#include <exception>

#include "ballsight/core/error.hpp"
#include "ballsight/core/utc_clock.hpp"

namespace ballsight {

BoundedFrameQueue::BoundedFrameQueue(std::size_t capacity)
    : capacity_(std::max<std::size_t>(capacity, 1)) {}

void BoundedFrameQueue::push_dropping_oldest(Frame frame) {
  {
    std::lock_guard lock(mutex_);
    if (closed_) return;
    while (frames_.size() >= capacity_) {
      frames_.pop_front();
      ++dropped_;
    }
    frames_.push_back(std::move(frame));
  }
  changed_.notify_all();
}

bool BoundedFrameQueue::push_waiting(Frame frame) {
  {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [this] { return closed_ || frames_.size() < capacity_; });
    if (closed_) return false;
    frames_.push_back(std::move(frame));
  }
  changed_.notify_all();
  return true;
}

std::optional<Frame> BoundedFrameQueue::pop(std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  if (!changed_.wait_for(lock, timeout, [this] { return closed_ || !frames_.empty(); }))
    return std::nullopt;
  if (frames_.empty()) return std::nullopt;
  Frame frame = std::move(frames_.front());
  frames_.pop_front();
  lock.unlock();
  changed_.notify_all();
  return frame;
}

std::optional<Frame> BoundedFrameQueue::pop_newest() {
  std::unique_lock lock(mutex_);
  if (frames_.empty()) return std::nullopt;
  dropped_ += frames_.size() - 1;
  Frame frame = std::move(frames_.back());
  frames_.clear();
  lock.unlock();
  changed_.notify_all();
  return frame;
}

void BoundedFrameQueue::close() {
  {
    std::lock_guard lock(mutex_);
    closed_ = true;
  }
  changed_.notify_all();
}

std::size_t BoundedFrameQueue::size() const {
  std::lock_guard lock(mutex_);
  return frames_.size();
}

std::uint64_t BoundedFrameQueue::dropped() const {
  std::lock_guard lock(mutex_);
  return dropped_;
}

void CaptureOptions::validate() const {
  require(queue_capacity >= 1 && queue_capacity <= 64, "capture queue_capacity",
          "must be within [1, 64]");
  backoff.validate();
}

CameraCapture::CameraCapture(std::string name, std::unique_ptr<FrameSource> source,
                             const CaptureOptions& options, CaptureLog log)
    : name_(std::move(name)),
      source_(std::move(source)),
      options_((options.validate(), options)),
      log_(std::move(log)),
      queue_(options.queue_capacity) {}

CameraCapture::~CameraCapture() {
  stop();
}

void CameraCapture::start() {
  if (thread_.joinable()) return;
  thread_ = std::thread([this] { run(); });
}

void CameraCapture::stop() {
  {
    std::lock_guard lock(mutex_);
    stop_requested_ = true;
  }
  stop_signal_.notify_all();
  queue_.close();
  if (thread_.joinable()) thread_.join();
}

CaptureStatus CameraCapture::status() const {
  std::lock_guard lock(mutex_);
  return status_;
}

bool CameraCapture::sleep_unless_stopped(std::chrono::milliseconds duration) {
  std::unique_lock lock(mutex_);
  return !stop_signal_.wait_for(lock, duration, [this] { return stop_requested_; });
}

void CameraCapture::set_state(CaptureState state) {
  std::lock_guard lock(mutex_);
  status_.state = state;
}

void CameraCapture::fail(const std::string& error) {
  std::chrono::milliseconds wait{};
  {
    std::lock_guard lock(mutex_);
    ++status_.failures_in_a_row;
    ++status_.failures_total;
    status_.last_error = error;
    status_.state = CaptureState::retrying;
    wait = options_.backoff.after(status_.failures_in_a_row);
  }
  if (log_) {
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.1f", static_cast<double>(wait.count()) / 1000.0);
    log_("camera " + name_ + ": " + error + "; retrying in " + seconds + " s");
  }
  sleep_unless_stopped(wait);
}

void CameraCapture::run() {
  bool open = false;
  while (true) {
    {
      std::lock_guard lock(mutex_);
      if (stop_requested_) {
        status_.state = CaptureState::stopped;
        return;
      }
    }
    try {
      if (!open) {
        source_->open();
        open = true;
      }
      std::optional<cv::Mat> image = source_->read();
      if (!image) {
        set_state(CaptureState::finished);
        queue_.close();
        return;
      }
      Frame frame{std::move(*image), 0, CaptureClock::now()};
      bool recovered = false;
      {
        std::lock_guard lock(mutex_);
        frame.sequence = status_.frames++;
        recovered = status_.failures_in_a_row > 0;
        status_.failures_in_a_row = 0;
        status_.state = CaptureState::running;
      }
      if (recovered && log_) log_("camera " + name_ + ": capturing again");
      if (source_->live()) {
        queue_.push_dropping_oldest(std::move(frame));
      } else if (!queue_.push_waiting(std::move(frame))) {
        set_state(CaptureState::stopped);
        return;
      }
    } catch (const std::exception& e) {
      open = false;
      fail(e.what());
    }
  }
}

std::optional<FrameSet> next_frame_set(const std::vector<CameraCapture*>& cameras,
                                       std::chrono::milliseconds timeout) {
  const auto deadline = CaptureClock::now() + timeout;
  const auto has_frame_or_ended = [](CameraCapture* camera) {
    return camera->frames().size() > 0 || camera->status().state == CaptureState::finished ||
           camera->status().state == CaptureState::stopped;
  };
  // Wait (polling the queues briefly) until every camera has a frame or has ended, or time's up.
  while (CaptureClock::now() < deadline &&
         !std::all_of(cameras.begin(), cameras.end(), has_frame_or_ended)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  FrameSet set;
  bool all_ended = true;
  for (std::size_t k = 0; k < cameras.size(); ++k) {
    CameraCapture* camera = cameras[k];
    std::optional<Frame> frame = camera->live()
                                     ? camera->frames().pop_newest()
                                     : camera->frames().pop(std::chrono::milliseconds(0));
    const CaptureState state = camera->status().state;
    all_ended &= state == CaptureState::finished || state == CaptureState::stopped;
    set.cameras.push_back(frame
                              ? CameraFrame{k, std::move(frame->image), utc_ns_of(frame->timestamp),
                                            frame->sequence, frame->timestamp}
                              : CameraFrame{k, {}, 0, 0, {}});
  }
  if (!set.any() && all_ended) return std::nullopt;
  return set;
}

}  // namespace ballsight
