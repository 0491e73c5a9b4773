#pragma once
// From a site file to a running court method: the calibrated cameras, the detector's and world
// model's options from the site's colours and sizes, and each camera's frame source.

#include <memory>
#include <vector>

#include "ballsight/camera/field_camera.hpp"
#include "ballsight/pipeline/court_pipeline.hpp"
#include "ballsight/pipeline/frame_source.hpp"
#include "ballsight/world/site.hpp"

namespace ballsight {

/// Every camera of the site with its intrinsics and pose from its calibration file. Throws
/// InputError naming the camera and file when the file has no pose yet (`court calibrate`).
std::vector<FieldCamera> site_field_cameras(const Site& site);

/// The area balls may lie in (the site's, with half a metre around it), field frame.
FieldRect site_area(const Site& site);

BallsightPipelineOptions ballsight_options_for_site(const Site& site);
/// The same for a service's sequence of frame sets: balls hidden by the robot remembered.
BallsightPipelineOptions service_pipeline_options(const Site& site);
/// The report's pipeline for the site: its marker boxes moved to the site's marker colours.
/// Throws InputError naming the colour when its box would not hold it (grey, or red).
SeedPipelineOptions seed_options_for_site(const Site& site);

/// What a court service's pipeline is made of beyond its site: enough to make the same pipeline
/// again (a recording keeps it, to replay the run).
struct ServicePipeline {
  CourtMethod method = CourtMethod::ballsight;  // seed: the report's pipeline
  std::vector<FieldCamera> cameras;
  /// Per camera, its view of the empty court (obstacles are looked for); empty: none.
  std::vector<cv::Mat> empty_court;
};

/// The service's pipeline for `site`: service_pipeline_options (with `setup`'s empty court) for
/// ballsight's, seed_options_for_site for the report's.
std::unique_ptr<CourtPipeline> make_service_pipeline(const Site& site,
                                                     const ServicePipeline& setup);

/// The camera's source: a file (one frame), a folder (its images in name order), a video device
/// or a URL.
std::unique_ptr<FrameSource> site_frame_source(const SiteCamera& camera);

}  // namespace ballsight
