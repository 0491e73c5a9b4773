#include "ballsight/dds/court_node.hpp"

#include "ballsight/core/error.hpp"
#include "ballsight/dds/court_messages.hpp"
#include "ballsight/dds/detection_messages.hpp"
#include "ballsight/pipeline/site_setup.hpp"

namespace ballsight::dds {
namespace {

using Clock = FrameSetAssembler::Clock;

}  // namespace

CameraFedCourtService::CameraFedCourtService(const Participant& participant, Site site,
                                             std::vector<FieldCamera> cameras,
                                             const CourtNodeOptions& options)
    : site_(std::move(site)), options_(options), waitset_(participant) {
  require(cameras.size() == site_.cameras.size(), "court node",
          "the site has " + std::to_string(site_.cameras.size()) + " cameras, " +
              std::to_string(cameras.size()) + " calibrations were given");
  publisher_ = std::make_unique<UpdatePublisher>(
      site_, ServicePipeline{CourtMethod::ballsight, std::move(cameras), {}}, options.planner);
  for (const SiteCamera& camera : site_.cameras) {
    readers_.push_back(
        std::make_unique<Reader<CameraDetectionsMsg>>(participant, detections_topic(camera.name)));
    waitset_.attach(readers_.back()->condition());
  }
  figures_.resize(site_.cameras.size());
}

CameraFedCourtService::~CameraFedCourtService() = default;

void CameraFedCourtService::take_frames(FrameSetAssembler& assembler) {
  for (std::size_t c = 0; c < readers_.size(); ++c) {
    readers_[c]->take([&](const CameraDetectionsMsg& message) {
      const Clock::time_point now = Clock::now();
      std::optional<std::vector<PixelDetection>> detections;
      std::string error;
      try {
        CameraFrameDetections frame = camera_detections_from_message(message);
        error = frame.error;
        if (error.empty()) detections = std::move(frame.detections);
      } catch (const InputError& e) {  // a bad message: this frame is not used, say why
        error = e.what();
      }
      assembler.add(c, stamp_ns(message.header), std::move(detections), now);
      const std::lock_guard lock(mutex_);
      CameraFigures& f = figures_[c];
      ++f.frames;
      f.last_frame = now;
      f.last_error = error;
    });
  }
}

void CameraFedCourtService::run(NavigationHub& hub, const std::atomic<bool>& stop) {
  FrameSetAssembler assembler(readers_.size(), options_.frame_sets);
  while (!stop) {
    waitset_.wait(std::chrono::milliseconds(20));
    take_frames(assembler);
    while (std::optional<DetectionSet> set = assembler.next(Clock::now()))
      publisher_->publish_detections(set->detections, set->capture_ns, hub);
    const std::lock_guard lock(mutex_);
    late_ = assembler.late_frames();
  }
}

void CameraFedCourtService::republish(NavigationHub& hub) {
  publisher_->republish(hub);
}

nlohmann::json CameraFedCourtService::health() const {
  nlohmann::json h = publisher_->health();
  const Clock::time_point now = Clock::now();
  nlohmann::json cameras = nlohmann::json::array();
  const std::lock_guard lock(mutex_);
  for (std::size_t c = 0; c < figures_.size(); ++c) {
    const CameraFigures& f = figures_[c];
    nlohmann::json camera = {
        {"name", site_.cameras[c].name}, {"frames", f.frames}, {"last_error", f.last_error}};
    if (f.last_frame) {
      const double age_s = std::chrono::duration<double>(now - *f.last_frame).count();
      camera["last_frame_age_s"] = age_s;
      camera["state"] =
          age_s <= std::chrono::duration<double>(options_.frame_sets.camera_timeout).count()
              ? "running"
              : "silent";
    } else {
      camera["last_frame_age_s"] = nullptr;
      camera["state"] = "waiting";
    }
    cameras.push_back(camera);
  }
  h["cameras"] = cameras;
  h["late_frames"] = late_;
  return h;
}

}  // namespace ballsight::dds
