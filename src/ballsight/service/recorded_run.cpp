#include "ballsight/service/recorded_run.hpp"

#include <map>

#include "ballsight/camera/image_file.hpp"
#include "ballsight/core/base64.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/service/navigation_json.hpp"
#include "ballsight/service/run_file.hpp"

namespace ballsight {
namespace {

using nlohmann::json;

// Thrown through the reader when the caller has seen enough.
struct Stop {};

}  // namespace

RecordedRun::RecordedRun(const std::filesystem::path& path)
    : path_(path), reader_(mcap::McapReader::open(path)) {
  const mcap::DataSection data = reader_.read();
  cut_ = data.cut;
  try {
    setup_ = read_run_setup(data.attachments, path.string());
  } catch (const InputError& e) {
    if (cut_.empty()) throw;
    throw InputError(std::string(e.what()) + " (the file is cut short: " + cut_ + ")");
  }
  for (const SiteCamera& camera : setup_.site.cameras) camera_names_.push_back(camera.name);
  for (const mcap::Metadata& m : data.metadata) {
    if (m.name != "ballsight") continue;
    if (const auto it = m.metadata.find("frames"); it != m.metadata.end()) frames_ = it->second;
  }
}

void RecordedRun::for_each_update(
    const std::function<bool(const RecordedUpdate&)>& on_update) const {
  const std::vector<std::string> topics = camera_topics(camera_names_);
  std::map<std::string, std::size_t> image_topics;
  for (std::size_t k = 0; k < topics.size(); ++k) image_topics[topics[k] + "/image"] = k;

  std::optional<RecordedUpdate> open;  // the update whose messages are being read
  ClientReports reports;               // as last recorded
  std::int64_t last_capture_ns = -1;
  const auto flush = [&](bool last) {
    if (!open) return;
    open->reports = reports;
    open->new_frame_set = open->capture_time_ns != last_capture_ns;
    open->cut_short = last && !cut_.empty();
    last_capture_ns = open->capture_time_ns;
    try {
      if (!on_update(*open)) throw Stop{};
    } catch (const json::exception& e) {
      throw InputError(path_.string() + ": update " + std::to_string(open->seq) + ": " + e.what());
    }
    open.reset();
  };
  const auto on_message = [&](const mcap::Channel& channel, const mcap::Message& message) {
    if (channel.topic == "/court") return;  // the file's, not an update's
    if (open && open->seq != message.sequence) flush(false);
    const std::string where = path_.string() + ": " + channel.topic + " message of update " +
                              std::to_string(message.sequence);
    try {
      if (channel.topic == "/navigation") {
        open.emplace();
        open->seq = message.sequence;
        open->navigation = json::parse(message.data.bytes);
        open->capture_time_ns = open->navigation.at("capture_time_ns").get<std::int64_t>();
        open->published_ns = open->navigation.at("published_ns").get<std::int64_t>();
        return;
      }
      if (!open) return;  // the rest of an update whose /navigation was cut off
      if (channel.topic == "/robot/reports") {
        reports = parse_client_reports(json::parse(message.data.bytes));
      } else if (const auto image = image_topics.find(channel.topic); image != image_topics.end()) {
        const std::size_t k = image->second;
        if (open->frames.cameras.empty()) {
          for (std::size_t c = 0; c < camera_names_.size(); ++c)
            open->frames.cameras.push_back({c, {}, 0, open->seq, {}});
        }
        const json body = json::parse(message.data.bytes);
        // Any size: a frame of another size than the calibration's goes to the pipeline, which
        // judges it as it did live (frame_problem).
        open->frames.cameras[k].image =
            decode_image_bgr(base64_decode(body.at("data").get<std::string>(), where), where);
        open->frames.cameras[k].capture_time_ns = static_cast<std::int64_t>(message.log_time);
      }
    } catch (const json::exception& e) {
      throw InputError(where + ": " + e.what());
    }
  };
  try {
    reader_.read(on_message);
    flush(true);
  } catch (const Stop&) {
  }
}

}  // namespace ballsight
