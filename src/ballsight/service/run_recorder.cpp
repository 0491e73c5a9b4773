#include "ballsight/service/run_recorder.hpp"

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

/// A camera's name as a part of a topic: letters, digits and '_' ("camera 0" -> "camera_0").
std::string topic_part(const std::string& name) {
  std::string part = name;
  for (char& c : part) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') c = '_';
  }
  return part;
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
  listener_ = hub_.add_listener([this](std::uint64_t seq) { on_published(seq); });
}

RecorderCounts RunRecorder::finish() {
  if (thread_.joinable()) {
    hub_.remove_listener(listener_);
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
  std::optional<NavigationUpdate> update = hub_.find(seq);
  if (!update) return;
  std::vector<CameraView> views;
  bool frames = false;
  for (std::size_t k = 0; k < camera_names_.size(); ++k) {
    std::optional<CameraView> view = service_.camera_view(k);
    const bool fresh = view && view->seq == seq && !view->frame.empty();
    frames = frames || fresh;
    views.push_back(fresh ? std::move(*view) : CameraView{});
  }
  const std::lock_guard lock(mutex_);
  if (stopping_ || !counts_.error.empty()) return;
  if (queue_.size() >= options_.queue) {
    ++counts_.dropped;
    return;
  }
  const bool keep = frames && options_.frame_every > 0 &&
                    frame_sets_seen_++ % static_cast<std::uint64_t>(options_.frame_every) == 0;
  if (!keep) views.clear();
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
  std::uint64_t number = 0;
  {
    const std::lock_guard lock(mutex_);
    number = ++counts_.files;
  }
  const std::filesystem::path path = numbered(options_.path, number);
  writer_ = std::make_unique<mcap::McapWriter>(
      path, mcap::WriterOptions{options_.compression, 1 << 20, "", "ballsight"});
  mcap::McapWriter& w = *writer_;
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
  for (const std::string& name : camera_names_) {
    channels_.push_back(w.add_channel(image, "/camera/" + topic_part(name) + "/image", "json"));
    channels_.push_back(
        w.add_channel(annotations, "/camera/" + topic_part(name) + "/detections", "json"));
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
}

void RunRecorder::write(const Job& job) {
  if (options_.max_mb > 0.0 && static_cast<double>(writer_->size()) >= options_.max_mb * 1e6) {
    writer_->close();
    bytes_closed_ += writer_->size();
    begin_file();
  }
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
    cv::imencode(".jpg", view.frame, bytes, jpeg);
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

json RunRecorder::health() const {
  const RecorderCounts c = counts();
  return {{"path", options_.path.string()},
          {"updates", c.updates},
          {"frame_sets", c.frame_sets},
          {"dropped", c.dropped},
          {"files", c.files},
          {"bytes", c.bytes},
          {"error", c.error}};
}

}  // namespace ballsight
