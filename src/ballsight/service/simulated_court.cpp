#include "ballsight/service/simulated_court.hpp"

#include <cmath>
#include <string>

#include "ballsight/sim/court_scenario.hpp"
#include "ballsight/sim/image_effects.hpp"
#include "ballsight/sim/seeding.hpp"

namespace ballsight {
namespace {

sim::CourtScene make_scene(const sim::CourtRig& rig, const SimulatedCourtOptions& options) {
  sim::CourtScenarioOptions scenario;
  scenario.ball_count = options.balls;
  scenario.cluster_share = options.cluster_share;
  scenario.layout = options.layout;
  scenario.obstacles = options.obstacles;
  sim::CourtScene scene =
      sim::make_court_scene(rig.court, scenario, sim::derive_seed(options.seed, 1));
  scene.effects.quantile_noise = true;  // 40 views a simulated second
  if (options.arrange) {
    options.arrange(scene);
    scene.validate();
  }
  return scene;
}

}  // namespace

SiteCourt site_court(const sim::TennisCourtSpec& court) {
  SiteCourt site;
  site.length_m = court.length_m;
  site.width_m = court.doubles_width_m;
  site.area_length_m = court.surround_length_m;
  site.area_width_m = court.surround_width_m;
  site.net = court.net.enabled;
  site.net_posts_outside_m = court.net.post_outside_doubles_m;
  site.net_height_posts_m = court.net.post_height_m;
  site.net_height_centre_m = court.net.centre_height_m;
  return site;
}

Site simulated_site(const sim::CourtRig& rig) {
  Site site;
  site.court = site_court(rig.court);
  site.robot.collector_width_m = 0.70;  // the report's collector (section 7.8)
  const std::vector<Vec3> references = sim::reference_ball_positions(rig.court);
  for (size_t i = 0; i < references.size(); ++i)
    site.reference_balls.push_back({"reference " + std::to_string(i), references[i].head<2>()});
  site.colours.reference_ball = Rgb::from_bgr(rig.court.reference_ball_bgr);
  site.colours.robot_front = Rgb::from_bgr(rig.court.robot_front_marker_bgr);
  site.colours.robot_back = Rgb::from_bgr(rig.court.robot_back_marker_bgr);
  for (size_t c = 0; c < rig.cameras.size(); ++c) {
    // The pole's corner, from the camera's side of the court (its rough place on the site plan).
    const Vec3 center = rig.cameras[c].center_in_field();
    const Vec3 hint(std::copysign(0.5 * rig.court.surround_length_m, center.x()),
                    std::copysign(0.5 * rig.court.surround_width_m, center.y()), 5.0);
    SiteCamera camera;
    camera.name = "camera " + std::to_string(c);
    camera.position_hint_m = hint;
    site.cameras.push_back(camera);
  }
  return site;
}

SimulatedCourt::SimulatedCourt(const SimulatedCourtOptions& options)
    : seed_(options.seed),
      rig_(sim::make_court_rig({}, {}, sim::derive_seed(options.seed, 0))),
      site_(simulated_site(rig_)),
      scene_(make_scene(rig_, options)) {
  for (const sim::CourtCamera& c : rig_.cameras) {
    renderers_.emplace_back(c, rig_.court);
    lit_.push_back(renderers_.back().lit_background(scene_.lighting, scene_.leaves));  // one sun
  }
}

std::vector<FieldCamera> SimulatedCourt::cameras() const {
  std::vector<FieldCamera> cameras;
  for (const sim::CourtCamera& c : rig_.cameras) cameras.push_back({c.camera, c.camera_from_field});
  return cameras;
}

cv::Mat SimulatedCourt::empty_court(std::size_t camera) const {
  cv::Mat view = lit_[camera].clone();
  sim::apply_image_effects(view, scene_.effects, sim::derive_seed(seed_, camera + 100));
  return view;
}

cv::Mat SimulatedCourt::render(std::size_t camera, const sim::CourtScene& scene,
                               std::uint64_t tick) const {
  return renderers_[camera]
      .render(scene, sim::derive_seed(seed_ + tick, camera + 2), lit_[camera])
      .bgr;
}

}  // namespace ballsight
