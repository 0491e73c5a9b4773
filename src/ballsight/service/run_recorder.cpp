#include "ballsight/service/run_recorder.hpp"

#include <algorithm>

#include "ballsight/core/error.hpp"
#include "ballsight/core/utc_clock.hpp"
#include "ballsight/service/navigation_json.hpp"

namespace ballsight {
namespace {

/// The n-th file of a recording (from 1): FILE.mcap, FILE-2.mcap, ...
std::filesystem::path numbered(const std::filesystem::path& first, std::uint64_t n) {
  if (n == 1) return first;
  return first.parent_path() /
         (first.stem().string() + "-" + std::to_string(n) + first.extension().string());
}

RunDescription describe_run(const NavigationHub& hub, const CourtService& service,
                            const RecordOptions& o) {
  RunDescription run{hub.service_id(),
                     service.camera_names(),
                     {service.site(), service.pipeline_setup(), service.planner_options()},
                     {},
                     o.frame_every,
                     o.compression,
                     o.frames,
                     o.jpeg_quality};
  run.setup_attachments = run_setup_attachments(run.setup, utc_now_ns());
  return run;
}

}  // namespace

void RecordOptions::validate() const {
  require(!path.empty(), "--record", "give the file to record into");
  require(frame_every >= 0, "--record-every", "must be 0 (no frames) or more");
  require(max_mb >= 0.0, "--record-max-mb", "must not be negative");
  require(jpeg_quality >= 1 && jpeg_quality <= 100, "--record-jpeg-quality", "must be 1-100");
  require(queue >= 1, "record queue", "must hold at least one update");
}

RunRecorder::RunRecorder(NavigationHub& hub, const CourtService& service, RecordOptions options)
    : hub_(hub),
      service_(service),
      options_(std::move(options)),
      run_(describe_run(hub, service, options_)),
      generation_(service.pipeline_generation()) {
  options_.validate();
  begin_file();
  thread_ = std::thread([this] { run(); });
  try {
    listener_ = hub_.add_listener([this](std::uint64_t seq) { on_published(seq); });
  } catch (...) {
    finish();
    throw;
  }
}

RecorderCounts RunRecorder::finish() {
  if (thread_.joinable()) {
    if (listener_ != 0) hub_.remove_listener(listener_);
    {
      const std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_all();
    room_.notify_all();
    thread_.join();
  }
  return counts();
}

RunRecorder::~RunRecorder() {
  finish();
}

void RunRecorder::on_published(std::uint64_t seq) {
  // Nothing is copied for an update that is dropped or not recorded.
  const auto full = [&](std::unique_lock<std::mutex>& lock) {
    if (options_.wait_for_room) {
      room_.wait(lock, [&] { return queue_.size() < options_.queue || stopping_; });
    }
    if (queue_.size() < options_.queue) return false;
    ++counts_.dropped;
    return true;
  };
  {
    std::unique_lock lock(mutex_);
    if (stopping_ || !counts_.error.empty() || full(lock)) return;
  }
  std::optional<NavigationUpdate> update = hub_.find(seq);
  if (!update) return;
  bool frames = false;
  {
    const std::lock_guard lock(mutex_);
    // A re-plan of the last world model (balls reported collected) brings no new frames.
    const bool frame_set = update->capture_time_ns != last_capture_ns_;
    last_capture_ns_ = update->capture_time_ns;
    frames = frame_set && options_.frame_every > 0 &&
             frame_sets_seen_++ % static_cast<std::uint64_t>(options_.frame_every) == 0;
  }
  std::vector<CameraView> views;
  for (std::size_t k = 0; frames && k < run_.camera_names.size(); ++k) {
    std::optional<CameraView> view = service_.camera_view(k);
    if (!view || view->seq != seq || view->frame.empty()) {
      views.emplace_back();  // this camera gave no frame to this update
      continue;
    }
    for (PixelDetection& d : view->detections) d.patch = {};  // the circle is what is drawn
    views.push_back(std::move(*view));
  }
  if (std::none_of(views.begin(), views.end(),
                   [](const CameraView& v) { return !v.frame.empty(); })) {
    views.clear();
  }
  std::unique_lock lock(mutex_);
  if (full(lock)) return;  // another publishing thread filled it meanwhile
  queue_.push_back({std::move(*update), std::move(views)});
  wake_.notify_one();
}

void RunRecorder::run() {
  while (true) {
    Job job;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
      if (queue_.empty()) break;
      job = std::move(queue_.front());
      queue_.pop_front();
    }
    room_.notify_all();
    try {
      write(job);
    } catch (const std::exception& e) {
      const std::lock_guard lock(mutex_);
      counts_.error = e.what();
      queue_.clear();
      room_.notify_all();
      break;
    }
  }
  try {
    file_->close();
  } catch (const std::exception& e) {
    const std::lock_guard lock(mutex_);
    if (counts_.error.empty()) counts_.error = e.what();
  }
  const std::lock_guard lock(mutex_);
  counts_.bytes = bytes_closed_ + file_->size();
}

void RunRecorder::begin_file() {
  const std::uint64_t number = files_begun_ + 1;
  auto next = std::make_unique<RunFile>(numbered(options_.path, number), run_, number);
  if (file_) {
    file_->close();
    bytes_closed_ += file_->size();
  }
  file_ = std::move(next);
  files_begun_ = number;
  updates_in_file_ = 0;
  reports_recorded_.clear();
  health_recorded_ns_ = 0;
  const std::lock_guard lock(mutex_);
  counts_.files = number;
  counts_.bytes = bytes_closed_ + file_->size();
}

void RunRecorder::write(const Job& job) {
  if (const std::uint64_t generation = service_.pipeline_generation(); generation != generation_) {
    // A camera re-calibrated: the next file says so, for a replay to use its new pose.
    generation_ = generation;
    run_ = describe_run(hub_, service_, options_);
    begin_file();
  } else if (options_.max_mb > 0.0 && updates_in_file_ > 0 &&
             static_cast<double>(file_->size()) >= options_.max_mb * 1e6) {
    begin_file();  // a file holds at least one update, however small the limit
  }
  ++updates_in_file_;
  const NavigationUpdate& u = job.update;
  file_->write_update(u, job.views);
  const nlohmann::json reports = client_reports_json(u.reports);
  if (std::string text = reports.dump(); text != reports_recorded_) {
    file_->write_side(RunFile::Side::reports, u, reports);
    reports_recorded_ = std::move(text);
  }
  if (u.published_ns - health_recorded_ns_ >= 1'000'000'000) {
    file_->write_side(RunFile::Side::health, u, service_.health());
    health_recorded_ns_ = u.published_ns;
  }
  std::optional<nlohmann::json> status;  // the drops so far, when there are new ones
  {
    const std::lock_guard lock(mutex_);
    ++counts_.updates;
    if (!job.views.empty()) ++counts_.frame_sets;
    if (counts_.dropped != dropped_recorded_) {
      dropped_recorded_ = counts_.dropped;
      status = {{"updates", counts_.updates},
                {"frame_sets", counts_.frame_sets},
                {"dropped", counts_.dropped}};
    }
  }
  if (status) file_->write_side(RunFile::Side::recorder, u, *status);
  const std::lock_guard lock(mutex_);
  counts_.bytes = bytes_closed_ + file_->size();
}

RecorderCounts RunRecorder::counts() const {
  const std::lock_guard lock(mutex_);
  return counts_;
}

}  // namespace ballsight
