#include "ballsight/service/run_file.hpp"

#include <algorithm>
#include <cctype>
#include <opencv2/imgcodecs.hpp>

#include "ballsight/core/file_io.hpp"
#include "ballsight/core/json_text.hpp"
#include "ballsight/core/utc_clock.hpp"
#include "ballsight/record/mcap_writer.hpp"
#include "ballsight/service/foxglove_messages.hpp"
#include "ballsight/service/navigation_json.hpp"

namespace ballsight {
namespace {

using nlohmann::json;

enum Topic : std::size_t {
  kNavigation,
  kBalls,
  kRobot,
  kRoute,
  kCourt,
  kRecorder,
  kReports,
  kHealth,
  kFixedTopics
};

/// A JSON object whose fields the docs list (docs/recording.md).
json object_schema() {
  return {{"type", "object"}};
}

json recorder_status_schema() {
  const json integer{{"type", "integer"}};
  return {{"type", "object"},
          {"properties", {{"updates", integer}, {"frame_sets", integer}, {"dropped", integer}}}};
}

}  // namespace

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

RunFile::RunFile(const std::filesystem::path& path, const RunDescription& run, std::uint64_t number)
    : run_(run) {
  mcap::WriterOptions options;
  options.compression = run.compression;
  writer_ = std::make_unique<mcap::McapWriter>(path, options);
  mcap::McapWriter& w = *writer_;
  const auto schema = [&](const char* name, const json& schema_json) {
    return w.add_schema(name, "jsonschema", json_text(schema_json));
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
                    "json"),
      w.add_channel(schema("ballsight.ClientReports", object_schema()), "/robot/reports", "json"),
      w.add_channel(schema("ballsight.Health", object_schema()), "/health", "json")};
  const std::uint16_t image =
      schema("foxglove.CompressedImage", foxglove::compressed_image_schema());
  const std::uint16_t annotations =
      schema("foxglove.ImageAnnotations", foxglove::image_annotations_schema());
  for (const std::string& topic : camera_topics(run.camera_names)) {
    channels_.push_back(w.add_channel(image, topic + "/image", "json"));
    channels_.push_back(w.add_channel(annotations, topic + "/detections", "json"));
  }

  const std::int64_t now = utc_now_ns();
  std::string cameras;
  for (const std::string& name : run.camera_names) cameras += (cameras.empty() ? "" : ",") + name;
  w.write_metadata({"ballsight",
                    {{"service_id", run.service_id},
                     {"cameras", cameras},
                     {"file", std::to_string(number)},
                     {"frame_every", std::to_string(run.frame_every)},
                     {"frames", run.frames == FrameEncoding::png ? "png" : "jpeg"},
                     {"compression", mcap::compression_name(run.compression)}}});
  // The site file and the cameras' calibrations, as they were when the file was begun.
  const Site& site = run.setup.site;
  std::vector<std::filesystem::path> files{site.file};
  for (const SiteCamera& camera : site.cameras) files.push_back(camera.calibration_file);
  for (const std::filesystem::path& file : files) {
    if (file.empty() || !std::filesystem::is_regular_file(file)) continue;
    w.attach({static_cast<std::uint64_t>(now),
              0,
              file.filename().string(),
              "application/yaml",
              {read_file(file)}});
  }
  for (const mcap::Attachment& a : run.setup_attachments) w.attach(a);
  put(kCourt, 0, now, now, foxglove::court_scene(site.court, now));
}

RunFile::~RunFile() = default;

void RunFile::put(std::size_t channel, std::uint32_t seq, std::int64_t time_ns,
                  std::int64_t publish_ns, const json& message) {
  writer_->write({channels_[channel],
                  seq,
                  static_cast<std::uint64_t>(time_ns),
                  static_cast<std::uint64_t>(publish_ns),
                  {json_text(message)}});
}

void RunFile::write_update(const NavigationUpdate& u, const std::vector<CameraView>& views) {
  const auto seq = static_cast<std::uint32_t>(u.seq);
  const auto put_at = [&](std::size_t channel, std::int64_t time_ns, const json& message) {
    put(channel, seq, time_ns, u.published_ns, message);
  };
  put_at(kNavigation, u.published_ns, navigation_json(u, run_.service_id, run_.camera_names));
  put_at(kBalls, u.capture_time_ns,
         foxglove::balls_scene(u.world, run_.setup.site.ball_radius_m, u.capture_time_ns));
  if (const std::optional<json> robot = foxglove::robot_pose(u.world, u.capture_time_ns)) {
    put_at(kRobot, u.capture_time_ns, *robot);
  }
  put_at(kRoute, u.capture_time_ns, foxglove::route_poses(u.route, u.capture_time_ns));
  const bool png = run_.frames == FrameEncoding::png;
  // PNG at zlib level 1: lossless at a third of level 3's time, a little larger.
  const std::vector<int> parameters =
      png ? std::vector<int>{cv::IMWRITE_PNG_COMPRESSION, 1}
          : std::vector<int>{cv::IMWRITE_JPEG_QUALITY, run_.jpeg_quality};
  for (std::size_t k = 0; k < views.size() && k < run_.camera_names.size(); ++k) {
    const CameraView& view = views[k];
    if (view.frame.empty()) continue;
    std::vector<std::uint8_t> bytes;
    if (!cv::imencode(png ? ".png" : ".jpg", view.frame, bytes, parameters)) {
      throw std::runtime_error("camera " + run_.camera_names[k] +
                               ": the frame does not encode as " + (png ? "PNG" : "JPEG"));
    }
    const std::string_view data(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    put_at(kFixedTopics + 2 * k, view.capture_ns,
           foxglove::compressed_image(data, png ? "png" : "jpeg", run_.camera_names[k],
                                      view.capture_ns));
    put_at(kFixedTopics + 2 * k + 1, view.capture_ns,
           foxglove::image_annotations(view.detections, view.capture_ns));
  }
}

void RunFile::write_side(Side topic, const NavigationUpdate& update, const json& message) {
  const Topic channel = topic == Side::recorder  ? kRecorder
                        : topic == Side::reports ? kReports
                                                 : kHealth;
  put(channel, static_cast<std::uint32_t>(update.seq), update.published_ns, update.published_ns,
      message);
}

void RunFile::close() {
  writer_->close();
}

std::uint64_t RunFile::size() const {
  return writer_->size();
}

}  // namespace ballsight
