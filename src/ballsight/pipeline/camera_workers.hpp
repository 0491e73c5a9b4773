#pragma once
// One long-lived thread per camera for the court pipeline's detection: a frame set's cameras are
// detected in parallel without starting a thread per frame set (std::async did, once per camera
// and frame set).

#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace ballsight {

class CameraWorkers {
 public:
  /// `count` threads, started at once, stopped and joined by the destructor.
  explicit CameraWorkers(std::size_t count);
  ~CameraWorkers();
  CameraWorkers(const CameraWorkers&) = delete;
  CameraWorkers& operator=(const CameraWorkers&) = delete;

  std::size_t size() const { return workers_.size(); }

  /// Runs jobs[k] on thread k (an empty job: nothing) and returns when every job has ended;
  /// rethrows the first exception a job threw. jobs.size() must be size(). Calls from several
  /// threads take turns.
  void run(const std::vector<std::function<void()>>& jobs);

 private:
  struct Worker {
    std::function<void()> job;  // the job of the current round; empty when done
    std::exception_ptr error;
    std::thread thread;
  };
  void serve(std::size_t k);

  std::mutex run_mutex_;          // held for a whole run(): one round at a time
  std::mutex mutex_;              // guards what follows
  std::condition_variable work_;  // a round began, or stop
  std::condition_variable done_;  // a worker ended its job
  std::vector<Worker> workers_;
  std::size_t busy_ = 0;  // workers with a job of this round
  std::size_t round_ = 0;
  bool stop_ = false;
};

}  // namespace ballsight
