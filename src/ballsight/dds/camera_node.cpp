#include "ballsight/dds/camera_node.hpp"

#include "ballsight/core/error.hpp"
#include "ballsight/pipeline/site_setup.hpp"
#include "ballsight/world/field_observation.hpp"

namespace ballsight::dds {

std::size_t site_camera_index(const Site& site, const std::string& name) {
  std::string names;
  for (std::size_t k = 0; k < site.cameras.size(); ++k) {
    if (site.cameras[k].name == name || std::to_string(k) == name) return k;
    names += (names.empty() ? "'" : ", '") + site.cameras[k].name + "'";
  }
  throw InputError("--camera: the site has no camera '" + name + "' (it has " + names +
                   ", or give its index from 0)");
}

CameraNode::CameraNode(const Participant& participant, const Site& site,
                       const std::vector<FieldCamera>& cameras, std::size_t camera,
                       const BallsightPipelineOptions& options)
    : name_(site.cameras.at(camera).name),
      field_camera_(cameras.at(camera)),
      world_(options.world),
      pipeline_(make_ballsight_pipeline({field_camera_}, options)),  // this camera's detector
      writer_(participant, detections_topic(name_)) {}

CameraNode::CameraNode(const Participant& participant, const Site& site,
                       const std::vector<FieldCamera>& cameras, std::size_t camera)
    : CameraNode(participant, site, cameras, camera, service_pipeline_options(site)) {}

CameraFrameDetections placed_detections(const std::string& name, const FieldCamera& camera,
                                        const CourtWorldOptions& world, std::uint64_t frame_index,
                                        std::int64_t capture_ns,
                                        std::vector<PixelDetection> detections) {
  CameraFrameDetections out{name, frame_index, capture_ns, "", std::move(detections), {}};
  for (const PixelDetection& d : out.detections) {
    const double height_m = object_center_height_m(d.object, world);
    const std::optional<FieldObservation> o = observe_on_plane(camera, d, height_m, world.noise);
    out.ground.push_back(
        o ? std::optional<Vec3>(Vec3(o->position_m.x(), o->position_m.y(), height_m))
          : std::nullopt);
  }
  return out;
}

CameraFrameDetections CameraNode::publish(const cv::Mat& frame, std::uint64_t frame_index,
                                          std::int64_t capture_ns) {
  std::string error = frame_problem(frame, field_camera_);
  CameraFrameDetections out = placed_detections(
      name_, field_camera_, world_, frame_index, capture_ns,
      error.empty() ? pipeline_->detect(0, frame) : std::vector<PixelDetection>{});
  out.error = std::move(error);
  MessageArena arena;
  writer_.write(camera_detections_message(out, arena));
  return out;
}

}  // namespace ballsight::dds
