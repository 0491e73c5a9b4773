#include "ballsight/service/run_recorder.hpp"

#include <algorithm>
#include <cctype>
#include <opencv2/imgcodecs.hpp>

#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/core/utc_clock.hpp"
#include "ballsight/record/mcap_writer.hpp"
#include "ballsight/service/foxglove_messages.hpp"
#include "ballsight/service/navigation_json.hpp"

namespace ballsight {
namespace {

using nlohmann::json;

std::string text(const json& j) {
  return j.dump(-1, ' ', false, json::error_handler_t::replace);
}

/// The n-th file of a recording (from 1): FILE.mcap, FILE-2.mcap, ...
std::filesystem::path numbered(const std::filesystem::path& first, std::uint64_t n) {
  if (n == 1) return first;
  return first.parent_path() /
         (first.stem().string() + "-" + std::to_string(n) + first.extension().string());
}

/// Each camera's topic prefix, "/camera/NAME" with the name's letters, digits and '_' (others
/// become '_': "camera 0" -> "camera_0"), made unique by its index where two would be the same.
std::vector<std::string> camera_topics(const std::vector<std::string>& names) {
  std::vector<std::string> topics;
  for (std::size_t k = 0; k < names.size(); ++k) {
    std::string topic = "/camera/";
    for (const char c : names[k]) {
      topic += std::isalnum(static_cast<unsigned char>(c)) || c == '_' ? c : '_';
    }
    if (std::find(topics.begin(), topics.end(), topic) != topics.end()) {
      topic += '_';
      topic += std::to_string(k);
    }
    topics.push_back(topic);
  }
  return topics;
}

enum Topic : std::size_t { kNavigation, kBalls, kRobot, kRoute, kCourt, kRecorder, kFixedTopics };

json recorder_status_schema() {
  const json integer{{"type", "integer"}};
  return {{"type", "object"},
          {"properties", {{"updates", integer}, {"frame_sets", integer}, {"dropped", integer}}}};
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
      camera_names_(service.camera_names()),
      site_(service.site()) {
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
    thread_.join();
  }
  return counts();
}

RunRecorder::~RunRecorder() {
  finish();
}

void RunRecorder::on_published(std::uint64_t seq) {
  // Nothing is copied for an update that is dropped or not recorded.
  const auto full = [&] {
    if (queue_.size() < options_.queue) return false;
    ++counts_.dropped;
    return true;
  };
  {
    const std::lock_guard lock(mutex_);
    if (stopping_ || !counts_.error.empty() || full()) return;
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
  for (std::size_t k = 0; frames && k < camera_names_.size(); ++k) {
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
  const std::lock_guard lock(mutex_);
  if (full()) return;  // another publishing thread filled it meanwhile
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
    try {
      write(job);
    } catch (const std::exception& e) {
      const std::lock_guard lock(mutex_);
      counts_.error = e.what();
      queue_.clear();
      break;
    }
  }
  try {
    writer_->close();
  } catch (const std::exception& e) {
    const std::lock_guard lock(mutex_);
    if (counts_.error.empty()) counts_.error = e.what();
  }
  const std::lock_guard lock(mutex_);
  counts_.bytes = bytes_closed_ + writer_->size();
}

void RunRecorder::begin_file() {
  const std::uint64_t number = files_begun_ + 1;
  mcap::WriterOptions writer_options;
  writer_options.compression = options_.compression;
  auto next = std::make_unique<mcap::McapWriter>(numbered(options_.path, number), writer_options);
  mcap::McapWriter& w = *next;
  const auto schema = [&](const char* name, const json& schema_json) {
    return w.add_schema(name, "jsonschema", text(schema_json));
  };
  const std::uint16_t scene = schema("foxglove.SceneUpdate", foxglove::scene_update_schema());
  channels_ = {
      w.add_channel(schema("ballsight.NavigationUpdate", foxglove::navigation_update_schema()),
                    "/navigation", "json"),
      w.add_channel(scene, "/balls", "json"),
      w.add_channel(schema("foxglove.PoseInFrame", foxglove::pose_in_frame_schema()), "/robot_pose",
                    "json"),
      w.add_channel(schema("foxglove.PosesInFrame", foxglove::poses_in_frame_schema()), "/route",
                    "json"),
      w.add_channel(scene, "/court", "json"),
      w.add_channel(schema("ballsight.RecorderStatus", recorder_status_schema()), "/recorder",
                    "json")};
  const std::uint16_t image =
      schema("foxglove.CompressedImage", foxglove::compressed_image_schema());
  const std::uint16_t annotations =
      schema("foxglove.ImageAnnotations", foxglove::image_annotations_schema());
  for (const std::string& topic : camera_topics(camera_names_)) {
    channels_.push_back(w.add_channel(image, topic + "/image", "json"));
    channels_.push_back(w.add_channel(annotations, topic + "/detections", "json"));
  }

  const std::int64_t now = utc_now_ns();
  std::string cameras;
  for (const std::string& name : camera_names_) cameras += (cameras.empty() ? "" : ",") + name;
  w.write_metadata({"ballsight",
                    {{"service_id", hub_.service_id()},
                     {"cameras", cameras},
                     {"file", std::to_string(number)},
                     {"frame_every", std::to_string(options_.frame_every)},
                     {"compression", mcap::compression_name(options_.compression)}}});
  // The site file and the cameras' calibrations, as they were when the file was begun.
  std::vector<std::filesystem::path> files{site_.file};
  for (const SiteCamera& camera : site_.cameras) files.push_back(camera.calibration_file);
  for (const std::filesystem::path& file : files) {
    if (file.empty() || !std::filesystem::is_regular_file(file)) continue;
    w.attach({static_cast<std::uint64_t>(now),
              0,
              file.filename().string(),
              "application/yaml",
              {read_file(file)}});
  }
  w.write({channels_[kCourt],
           0,
           static_cast<std::uint64_t>(now),
           static_cast<std::uint64_t>(now),
           {text(foxglove::court_scene(site_.court, now))}});
  if (writer_) {
    writer_->close();
    bytes_closed_ += writer_->size();
  }
  writer_ = std::move(next);
  files_begun_ = number;
  updates_in_file_ = 0;
  const std::lock_guard lock(mutex_);
  counts_.files = number;
  counts_.bytes = bytes_closed_ + writer_->size();
}

void RunRecorder::write(const Job& job) {
  // A file holds at least one update, however small the limit.
  if (options_.max_mb > 0.0 && updates_in_file_ > 0 &&
      static_cast<double>(writer_->size()) >= options_.max_mb * 1e6) {
    begin_file();
  }
  ++updates_in_file_;
  const NavigationUpdate& u = job.update;
  const auto seq = static_cast<std::uint32_t>(u.seq);
  const auto put = [&](std::size_t channel, std::int64_t time_ns, const json& message) {
    writer_->write({channels_[channel],
                    seq,
                    static_cast<std::uint64_t>(time_ns),
                    static_cast<std::uint64_t>(u.published_ns),
                    {text(message)}});
  };
  put(kNavigation, u.published_ns, navigation_json(u, hub_.service_id(), camera_names_));
  put(kBalls, u.capture_time_ns,
      foxglove::balls_scene(u.world, site_.ball_radius_m, u.capture_time_ns));
  if (const std::optional<json> robot = foxglove::robot_pose(u.world, u.capture_time_ns)) {
    put(kRobot, u.capture_time_ns, *robot);
  }
  put(kRoute, u.capture_time_ns, foxglove::route_poses(u.route, u.capture_time_ns));
  const std::vector<int> jpeg{cv::IMWRITE_JPEG_QUALITY, options_.jpeg_quality};
  for (std::size_t k = 0; k < job.views.size(); ++k) {
    const CameraView& view = job.views[k];
    if (view.frame.empty()) continue;
    std::vector<std::uint8_t> bytes;
    if (!cv::imencode(".jpg", view.frame, bytes, jpeg)) {
      throw std::runtime_error("camera " + camera_names_[k] +
                               ": the frame does not encode as JPEG");
    }
    const std::string_view data(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    put(kFixedTopics + 2 * k, view.capture_ns,
        foxglove::compressed_image(data, camera_names_[k], view.capture_ns));
    put(kFixedTopics + 2 * k + 1, view.capture_ns,
        foxglove::image_annotations(view.detections, view.capture_ns));
  }
  std::optional<json> status;  // the drops so far, when there are new ones
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
  if (status) put(kRecorder, u.published_ns, *status);
  const std::lock_guard lock(mutex_);
  counts_.bytes = bytes_closed_ + writer_->size();
}

RecorderCounts RunRecorder::counts() const {
  const std::lock_guard lock(mutex_);
  return counts_;
}

}  // namespace ballsight
