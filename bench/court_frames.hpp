#pragma once
// Four 1920x1080 frames of the simulated court (the report's IP cameras, one per corner camera),
// rendered once per court surface, for the benchmarks of what happens to a frame set.

#include <opencv2/core.hpp>
#include <vector>

#include "ballsight/eval/court_eval_calibration.hpp"
#include "ballsight/pipeline/court_pipeline.hpp"
#include "ballsight/pipeline/site_setup.hpp"
#include "ballsight/sim/court_renderer.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "ballsight/sim/court_scenario.hpp"
#include "ballsight/sim/tennis_court.hpp"

namespace ballsight::bench {

struct Setup {
  std::vector<FieldCamera> cameras;
  FrameSet frames;
  BallsightPipelineOptions options;  // the simulated site's: the court's marker colours
  Site site;                         // the simulated site (no files)
};

// 40 balls (a quarter in clusters, some by the robot), the weather of scene 7, noise: rendered
// once per court surface.
inline Setup render_setup(sim::CourtSurface surface, bool obstacles = false) {
  cv::setNumThreads(1);
  sim::TennisCourtSpec court;
  sim::set_court_surface(court, surface);
  sim::CourtRigOptions report_cameras;
  report_cameras.width = sim::kReportCameraWidth;
  report_cameras.height = sim::kReportCameraHeight;
  const sim::CourtRig rig = sim::make_court_rig(court, report_cameras, 1);
  sim::CourtScenarioOptions options;
  options.ball_count = 40;
  if (obstacles) options.obstacles.people = options.obstacles.bags = 1;
  const sim::CourtScene scene = sim::make_court_scene(rig.court, options, 7);
  Setup out;
  out.site = simulated_site(rig);
  out.options = ballsight_options_for_site(out.site);
  for (const sim::CourtCamera& camera : rig.cameras) {
    const sim::CourtRenderer renderer(camera, rig.court);
    out.cameras.push_back({camera.camera, camera.camera_from_field});
    out.frames.cameras.push_back(
        {out.frames.cameras.size(), renderer.render(scene, 3).bgr, 0, 0, {}});
    if (obstacles) {
      cv::Mat empty = renderer.lit_background(scene.lighting, scene.leaves);
      sim::apply_image_effects(empty, scene.effects, 11);
      out.options.empty_court.push_back(empty);
    }
  }
  return out;
}

inline const Setup& setup() {
  static const Setup s = render_setup(sim::CourtSurface::green);
  return s;
}

}  // namespace ballsight::bench
