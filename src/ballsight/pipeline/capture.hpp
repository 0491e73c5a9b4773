#pragma once
// Capture: one thread per camera reads its source into a small bounded queue. A live source's
// queue drops its oldest frame when full (the world model wants the newest view, not a backlog);
// a recorded source waits for room instead, so every frame is used. A source that cannot be
// opened or fails is reopened with exponential back-off while the other cameras go on; frame
// sets take the newest frame of every camera that has one and say which cameras are missing.

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "ballsight/pipeline/frame_set.hpp"
#include "ballsight/pipeline/frame_source.hpp"

namespace ballsight {

using CaptureClock = std::chrono::steady_clock;

struct Frame {
  cv::Mat image;
  std::uint64_t sequence = 0;          // frames read from this source so far, from 0
  CaptureClock::time_point timestamp;  // when the capture thread received it
};

class BoundedFrameQueue {
 public:
  explicit BoundedFrameQueue(std::size_t capacity);

  /// Adds a frame; when full, the oldest is dropped first.
  void push_dropping_oldest(Frame frame);
  /// Adds a frame; when full, waits for room. False when the queue was closed meanwhile.
  bool push_waiting(Frame frame);
  /// The oldest frame, waiting up to `timeout`; nullopt on timeout or when closed and empty.
  std::optional<Frame> pop(std::chrono::milliseconds timeout);
  /// The newest frame, dropping any older ones; nullopt when empty.
  std::optional<Frame> pop_newest();
  /// Wakes every waiter; pushes fail from now on, pops drain what is left.
  void close();

  std::size_t size() const;
  std::uint64_t dropped() const;  // frames dropped as stale

 private:
  const std::size_t capacity_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Frame> frames_;
  std::uint64_t dropped_ = 0;
  bool closed_ = false;
};

struct CaptureOptions {
  std::size_t queue_capacity = 2;
  BackoffOptions backoff;  // 0.2 s, 0.4 s, ... up to 5 s

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

enum class CaptureState { starting, running, retrying, finished, stopped };

struct CaptureStatus {
  CaptureState state = CaptureState::starting;
  int failures_in_a_row = 0;
  int failures_total = 0;
  std::string last_error;
  std::uint64_t frames = 0;
};

/// Called from the capture thread with a message on every failure and recovery.
using CaptureLog = std::function<void(const std::string& message)>;

class CameraCapture {
 public:
  CameraCapture(std::string name, std::unique_ptr<FrameSource> source,
                const CaptureOptions& options, CaptureLog log = {});
  ~CameraCapture();  // stops and joins
  CameraCapture(const CameraCapture&) = delete;
  CameraCapture& operator=(const CameraCapture&) = delete;

  void start();
  void stop();

  const std::string& name() const { return name_; }
  bool live() const { return source_->live(); }
  BoundedFrameQueue& frames() { return queue_; }
  CaptureStatus status() const;

 private:
  void run();
  bool sleep_unless_stopped(std::chrono::milliseconds duration);
  void set_state(CaptureState state);
  void fail(const std::string& error);

  std::string name_;
  std::unique_ptr<FrameSource> source_;
  CaptureOptions options_;
  CaptureLog log_;
  BoundedFrameQueue queue_;
  mutable std::mutex mutex_;
  std::condition_variable stop_signal_;
  bool stop_requested_ = false;
  CaptureStatus status_;
  std::thread thread_;
};

/// Waits up to `timeout` until every camera that is still capturing (not finished) has a frame,
/// then takes one from each: the oldest of a recorded source (every frame in turn), the newest of
/// a live one, stamped with when its capture thread received it (UTC); an empty image where a
/// camera had none. nullopt when every camera has finished and has nothing left.
std::optional<FrameSet> next_frame_set(const std::vector<CameraCapture*>& cameras,
                                       std::chrono::milliseconds timeout);

}  // namespace ballsight
