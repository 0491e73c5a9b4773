#include "ballsight/pipeline/camera_workers.hpp"

#include <cassert>

namespace ballsight {

CameraWorkers::CameraWorkers(std::size_t count) : workers_(count) {
  for (std::size_t k = 0; k < count; ++k) workers_[k].thread = std::thread([this, k] { serve(k); });
}

CameraWorkers::~CameraWorkers() {
  {
    const std::lock_guard lock(mutex_);
    stop_ = true;
  }
  work_.notify_all();
  for (Worker& w : workers_) w.thread.join();
}

void CameraWorkers::run(const std::vector<std::function<void()>>& jobs) {
  assert(jobs.size() == workers_.size());
  const std::lock_guard one_round(run_mutex_);
  std::unique_lock lock(mutex_);
  assert(busy_ == 0);
  for (std::size_t k = 0; k < workers_.size(); ++k) {
    workers_[k].error = nullptr;
    workers_[k].job = jobs[k];
    if (workers_[k].job) ++busy_;
  }
  ++round_;
  work_.notify_all();
  done_.wait(lock, [this] { return busy_ == 0; });
  for (const Worker& w : workers_) {
    if (w.error) std::rethrow_exception(w.error);
  }
}

void CameraWorkers::serve(std::size_t k) {
  std::size_t seen = 0;  // the last round this worker looked at
  std::unique_lock lock(mutex_);
  for (;;) {
    work_.wait(lock, [&] { return stop_ || round_ != seen; });
    if (stop_) return;
    seen = round_;
    if (!workers_[k].job) continue;
    const std::function<void()> job = std::move(workers_[k].job);
    workers_[k].job = nullptr;
    lock.unlock();
    std::exception_ptr error;
    try {
      job();
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    workers_[k].error = error;
    if (--busy_ == 0) done_.notify_one();
  }
}

}  // namespace ballsight
