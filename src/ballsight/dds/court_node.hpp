#pragma once
// `ballsight court-node`: a court's fusion and planning fed by its camera nodes over DDS. Each
// camera's detections (`cameras/<camera>/detections`) are gathered into frame sets
// (frame_sets.hpp), fused by the court pipeline's second half, planned and published into the
// hub like any court service's (CourtTopics then writes them as ROS 2 topics).

#include <memory>
#include <mutex>

#include "ballsight/dds/frame_sets.hpp"
#include "ballsight/dds/message_types.hpp"
#include "ballsight/dds/topic_io.hpp"
#include "ballsight/service/court_service.hpp"

namespace ballsight::dds {

struct CourtNodeOptions {
  PlannerOptions planner;
  FrameSetPolicy frame_sets;
};

class CameraFedCourtService : public CourtService {
 public:
  /// `cameras`: the site's cameras, calibrated, in site order. Throws InputError for a site whose
  /// cameras and `cameras` disagree.
  CameraFedCourtService(const Participant& participant, Site site, std::vector<FieldCamera> cameras,
                        const CourtNodeOptions& options);
  ~CameraFedCourtService() override;

  const Site& site() const override { return site_; }
  void run(NavigationHub& hub, const std::atomic<bool>& stop) override;
  void republish(NavigationHub& hub) override;
  /// Per camera: "state" (waiting before its first frame, running, silent when not heard for
  /// the camera timeout), "frames", "last_frame_age_s", "last_error"; "late_frames", and the
  /// figures of UpdatePublisher::health().
  nlohmann::json health() const override;

 protected:
  UpdatePublisher& publisher() const override { return *publisher_; }

 private:
  struct CameraFigures {
    std::uint64_t frames = 0;
    std::optional<FrameSetAssembler::Clock::time_point> last_frame;
    std::string last_error;
  };
  void take_frames(FrameSetAssembler& assembler);

  Site site_;
  CourtNodeOptions options_;
  std::unique_ptr<UpdatePublisher> publisher_;
  std::vector<std::unique_ptr<Reader<CameraDetectionsMsg>>> readers_;
  WaitSet waitset_;
  mutable std::mutex mutex_;  // guards figures_, late_
  std::vector<CameraFigures> figures_;
  std::uint64_t late_ = 0;
};

}  // namespace ballsight::dds
