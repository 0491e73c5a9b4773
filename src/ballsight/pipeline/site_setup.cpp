#include "ballsight/pipeline/site_setup.hpp"

#include <string>

#include "ballsight/camera/camera_file.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/detect/seed_detector.hpp"

namespace ballsight {

std::vector<FieldCamera> site_field_cameras(const Site& site) {
  std::vector<FieldCamera> cameras;
  for (const SiteCamera& camera : site.cameras) {
    const CameraCalibration calibration = read_camera_file(camera.calibration_file);
    require(calibration.extrinsics.has_value(),
            "camera '" + camera.name + "' (" + camera.calibration_file.string() + ")",
            "has no pose yet: run `ballsight court calibrate --site " + site.file.string() + "`");
    cameras.push_back(
        {PinholeCamera(calibration.intrinsics), calibration.extrinsics->camera_from_field});
  }
  return cameras;
}

FieldRect site_area(const Site& site) {
  const FieldRect fenced = site.court.fenced_area();
  const Vec2 margin(0.5, 0.5);
  return {fenced.min_m - margin, fenced.max_m + margin};
}

BallsightPipelineOptions service_pipeline_options(const Site& site) {
  BallsightPipelineOptions options = ballsight_options_for_site(site);
  options.remember_hidden_balls = true;
  return options;
}

BallsightPipelineOptions ballsight_options_for_site(const Site& site) {
  BallsightPipelineOptions options;
  CourtObjectColours colours;
  colours.ball = site.colours.ball.bgr();
  colours.front_marker = site.colours.robot_front.bgr();
  colours.back_marker = site.colours.robot_back.bgr();
  options.detector.objects = court_objects(colours, site.ball_radius_m, site.robot.marker_radius_m,
                                           site.robot.marker_height_m);
  options.detector.area = site_area(site);
  options.world.ball_radius_m = site.ball_radius_m;
  options.world.robot.marker_height_m = site.robot.marker_height_m;
  options.world.collector_width_m = site.robot.collector_width_m;
  options.world.area = site_area(site);
  if (site.court.net) {
    options.world.support.net =
        NetPanel{site.court.width_m / 2.0 + site.court.net_posts_outside_m,
                 site.court.net_height_posts_m, site.court.net_height_centre_m};
    options.world.obstacles.net = options.world.support.net;
  }
  return options;
}

namespace {

// The report's marker box moved from its own colour to the site's; InputError naming `key` when
// the moved box does not hold the site's colour or was cut at hue 0 or 179.
HsvRange marker_box(const HsvRange& box, const Rgb& plain, const Rgb& colour, const char* key) {
  const HsvRange moved = hue_moved(box, plain.bgr(), colour.bgr());
  const bool whole = moved.max[0] - moved.min[0] == box.max[0] - box.min[0];
  require(whole && moved.contains_bgr(colour.bgr()), key,
          "the report's HSV box moved to this colour (H " + std::to_string(moved.min[0]) + "-" +
              std::to_string(moved.max[0]) + ", S >= " + std::to_string(moved.min[1]) +
              ", V >= " + std::to_string(moved.min[2]) +
              ") does not hold it: too grey, pale or dark, or red across hue 0; choose a "
              "saturated colour away from red for the report's method");
  return moved;
}

}  // namespace

std::unique_ptr<CourtPipeline> make_service_pipeline(const Site& site,
                                                     const ServicePipeline& setup) {
  if (setup.method == CourtMethod::seed)
    return make_seed_pipeline(setup.cameras, seed_options_for_site(site));
  BallsightPipelineOptions options = service_pipeline_options(site);
  options.empty_court = setup.empty_court;
  return make_ballsight_pipeline(setup.cameras, options);
}

SeedPipelineOptions seed_options_for_site(const Site& site) {
  SeedPipelineOptions options;
  // The markers' boxes follow the site's marker colours.
  const SiteColours plain;
  options.detector.front_marker = marker_box(options.detector.front_marker, plain.robot_front,
                                             site.colours.robot_front, "colours.robot_front");
  options.detector.back_marker = marker_box(options.detector.back_marker, plain.robot_back,
                                            site.colours.robot_back, "colours.robot_back");
  options.world.merge_distance_m = site.robot.collector_width_m;
  options.world.robot.marker_height_m = site.robot.marker_height_m;
  return options;
}

std::unique_ptr<FrameSource> site_frame_source(const SiteCamera& camera) {
  const CameraSource& source = camera.source;
  switch (source.kind) {
    case CameraSource::Kind::file:
      return make_image_files_source({source.path}, "file " + source.path.string());
    case CameraSource::Kind::folder:
      return make_image_folder_source(source.path);
    case CameraSource::Kind::device:
      return make_device_source(source.device);
    case CameraSource::Kind::url:
      return make_url_source(source.url);
  }
  throw InputError("camera '" + camera.name + "': unknown source kind");
}

}  // namespace ballsight
