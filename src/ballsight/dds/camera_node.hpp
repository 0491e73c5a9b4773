#pragma once
// `ballsight camera-node`: one camera's half of the court pipeline next to the camera. Each frame
// is detected (the court pipeline's first half), every object placed on the court with the
// camera's pose, and the detections written on `cameras/<camera>/detections` with the frame's
// capture time, for the court node to fuse.

#include <memory>
#include <opencv2/core.hpp>

#include "ballsight/dds/detection_messages.hpp"
#include "ballsight/dds/topic_io.hpp"
#include "ballsight/pipeline/court_pipeline.hpp"
#include "ballsight/world/court_world.hpp"
#include "ballsight/world/site.hpp"

namespace ballsight::dds {

class CameraNode {
 public:
  /// Camera `camera` of `site`, calibrated as `cameras` (the site's, in site order). Throws
  /// InputError when `camera` is not one of them.
  CameraNode(const Participant& participant, const Site& site,
             const std::vector<FieldCamera>& cameras, std::size_t camera);

  /// Detects `frame` (captured at `capture_ns`, UTC) and writes its detections; returns them.
  /// A frame the camera's calibration does not fit is written with its error and no detections.
  CameraFrameDetections publish(const cv::Mat& frame, std::uint64_t frame_index,
                                std::int64_t capture_ns);
  const std::string& camera_name() const { return name_; }

 private:
  CameraNode(const Participant& participant, const Site& site,
             const std::vector<FieldCamera>& cameras, std::size_t camera,
             const BallsightPipelineOptions& options);

  std::string name_;
  FieldCamera field_camera_;
  CourtWorldOptions world_;
  std::unique_ptr<CourtPipeline> pipeline_;  // of this camera alone (its index 0)
  Writer<CameraDetectionsMsg> writer_;
};

/// `detections` of camera `name` (calibrated as `camera`) in frame `frame_index`, each object's
/// centre placed on its height plane of the court (`world`'s object heights) where it can be.
CameraFrameDetections placed_detections(const std::string& name, const FieldCamera& camera,
                                        const CourtWorldOptions& world, std::uint64_t frame_index,
                                        std::int64_t capture_ns,
                                        std::vector<PixelDetection> detections);

/// The index of the camera named `name` (or given by its index, "0", "1", ...) in `site`;
/// throws InputError listing the names.
std::size_t site_camera_index(const Site& site, const std::string& name);

}  // namespace ballsight::dds
