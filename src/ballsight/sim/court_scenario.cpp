#include "ballsight/sim/court_scenario.hpp"

#include <cmath>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/enum_names.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/sim/seeding.hpp"
#include "ballsight/sim/tennis_net.hpp"

namespace ballsight::sim {
namespace {

constexpr double kBallGapM = 0.002;  // between touching balls: no interpenetration

/// Distance on the floor from `xy` to the footprint of `box` (0 inside it).
double footprint_distance(const FloorBox& box, const Vec2& xy) {
  const Vec2 p = box.pose.field_from_robot().inverse() * xy;
  const Vec2 outside(std::max(std::abs(p.x()) - box.half_size.x(), 0.0),
                     std::max(std::abs(p.y()) - box.half_size.y(), 0.0));
  return outside.norm();
}

FloorBox footprint(const RobotBox& robot) {
  return {robot.pose, Vec2(robot.length_m / 2.0, robot.width_m / 2.0), robot.height_m};
}

/// The net's footprint (posts included), or nothing when the court has no net.
std::optional<FloorBox> net_footprint(const TennisCourtSpec& court) {
  const std::optional<TennisNet> net = TennisNet::of(court);
  return net ? std::optional<FloorBox>(net->bounds()) : std::nullopt;
}

/// Free space on the ground: balls already placed, the robot's footprint and the net's.
class Placement {
 public:
  Placement(const RobotBox& robot, const std::optional<FloorBox>& net)
      : robot_(footprint(robot)), net_(net) {}

  void add(const SceneSphere& s) { taken_.push_back(s); }

  bool is_free(const Vec2& xy, double radius) const {
    for (const SceneSphere& s : taken_) {
      if ((s.center_in_field.head<2>() - xy).norm() < s.radius_m + radius + kBallGapM) {
        return false;
      }
    }
    if (net_ && footprint_distance(*net_, xy) < radius + kBallGapM) return false;
    return footprint_distance(robot_, xy) >= radius + kBallGapM;
  }

 private:
  FloorBox robot_;
  std::optional<FloorBox> net_;
  std::vector<SceneSphere> taken_;
};

Vec2 uniform_in(std::mt19937_64& rng, const GroundRect& r, double margin) {
  return {uniform(rng, r.x_min + margin, r.x_max - margin),
          uniform(rng, r.y_min + margin, r.y_max - margin)};
}

/// Draws candidates until one is free; scenes are sparse, so failure is a bug.
template <typename Draw>
Vec2 place(std::mt19937_64& rng, const Placement& placement, double radius, Draw draw) {
  for (int attempt = 0; attempt < 10000; ++attempt) {
    const Vec2 xy = draw(rng);
    if (placement.is_free(xy, radius)) return xy;
  }
  throw std::logic_error("court scenario: no free place for a ball");
}

/// A place for a ball of `layout` (not scattered); the caller checks that it is free.
Vec2 laid_out(std::mt19937_64& rng, const TennisCourtSpec& court, BallLayout layout) {
  const double r = kTennisBallRadiusM;
  const GroundRect fence = court.surround_rect();
  const double side = uniform_int(rng, 0, 1) == 1 ? 1.0 : -1.0;
  switch (layout) {
    case BallLayout::along_net: {
      const double post_y = TennisNet::of(court) ? court.doubles_width_m / 2.0 : fence.y_max;
      return {side * uniform(rng, 0.0, 0.30), uniform(rng, -post_y, post_y)};
    }
    case BallLayout::along_fence: {
      const double in = uniform(rng, r + 0.005, 0.20);
      const double along = uniform(rng, 0.0, 1.0);
      const double w = fence.x_max - fence.x_min, h = fence.y_max - fence.y_min;
      if (uniform(rng, 0.0, w + h) < w) {  // a long side, by length
        return {fence.x_min + along * w, side > 0 ? fence.y_max - in : fence.y_min + in};
      }
      return {side > 0 ? fence.x_max - in : fence.x_min + in, fence.y_min + along * h};
    }
    case BallLayout::net_posts: {
      const std::optional<TennisNet> net = TennisNet::of(court);
      const Vec2 post = net ? net->post_positions()[side > 0 ? 1 : 0] : Vec2(0.0, side * 5.0);
      const double a = uniform(rng, -kPi, kPi), d = uniform(rng, 0.05, 0.60);
      return post + d * Vec2(std::cos(a), std::sin(a));
    }
    case BallLayout::scattered:
      break;
  }
  throw std::logic_error("laid_out: scattered balls are drawn by the caller");
}

SceneSphere tennis_ball(int id, const Vec2& xy) {
  return {ObjectKind::tennis_ball, id, Vec3(xy.x(), xy.y(), kTennisBallRadiusM), kTennisBallRadiusM,
          kTennisBallBgr};
}

// Sun: 35-70 deg high, 40-50 % sky light, a soft-edged band (trees). Hard shadow: 20-40 deg
// high, 25-35 % sky light, a wide band with an edge of a few cm (a building). Overcast: the light
// comes from the whole sky (modelled as a weak sun at the zenith over 60-75 % sky light), no
// band; the scene is darker (the brightness gain is drawn lower, make_court_scene). Indoor: a
// hall's many ceiling lamps, modelled like overcast (its colour cast: make_court_scene).
Lighting random_lighting(std::mt19937_64& rng, const TennisCourtSpec& court, bool shadow,
                         LightCondition condition) {
  Lighting lighting;
  lighting.condition = condition;
  const bool hard = condition == LightCondition::hard_shadow;
  const bool top_lit = condition == LightCondition::overcast || condition == LightCondition::indoor;
  const double elevation =
      top_lit ? kPi / 2.0
              : rad_from_deg(hard ? uniform(rng, 20.0, 40.0) : uniform(rng, 35.0, 70.0));
  const double azimuth = uniform(rng, -kPi, kPi);
  lighting.to_sun = Vec3(std::cos(elevation) * std::cos(azimuth),
                         std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
  lighting.ambient = top_lit ? uniform(rng, 0.60, 0.75)
                     : hard  ? uniform(rng, 0.25, 0.35)
                             : uniform(rng, 0.40, 0.50);
  if (shadow && !top_lit) {
    const Vec2 point = uniform_in(rng, court.court_rect(), 1.0);
    const double direction = uniform(rng, 0.0, kPi);
    lighting.shadow = ShadowBand{point, Vec2(std::cos(direction), std::sin(direction)),
                                 hard ? uniform(rng, 3.0, 8.0) : uniform(rng, 2.0, 5.0),
                                 hard ? uniform(rng, 0.02, 0.06) : uniform(rng, 0.2, 0.6)};
  }
  return lighting;
}

// A colour drawn uniformly per channel between `lo` and `hi` (BGR), red first: in the order
// GCC evaluated the three draws when they were a constructor's arguments, so scenes stay as
// they were.
cv::Vec3b uniform_bgr(std::mt19937_64& rng, const cv::Vec3d& lo, const cv::Vec3d& hi) {
  cv::Vec3b out;
  for (int c = 2; c >= 0; --c) out[c] = cv::saturate_cast<uchar>(uniform(rng, lo[c], hi[c]));
  return out;
}

// Worn felt: paler, towards a dirty light grey.
cv::Vec3b worn_colour(const cv::Vec3b& fresh, double wear) {
  const cv::Vec3d grey(185.0, 195.0, 195.0);
  cv::Vec3b out;
  for (int c = 0; c < 3; ++c)
    out[c] = cv::saturate_cast<uchar>((1.0 - wear) * fresh[c] + wear * grey[c]);
  return out;
}

// A fallen leaf anywhere on the fenced surface: 8-18 cm long, yellow-green (the colour of a
// ball in the shade or the sun) or, one in four, dry and brown.
FloorLeaf random_leaf(std::mt19937_64& rng, const TennisCourtSpec& court) {
  FloorLeaf leaf;
  leaf.center_in_field = uniform_in(rng, court.surround_rect(), 0.2);
  const double angle = uniform(rng, 0.0, kPi);
  leaf.axis = Vec2(std::cos(angle), std::sin(angle));
  leaf.half_length_m = uniform(rng, 0.04, 0.09);
  leaf.half_width_m = leaf.half_length_m * uniform(rng, 0.35, 0.6);
  const bool dry = uniform_int(rng, 0, 3) == 0;
  leaf.bgr = dry ? uniform_bgr(rng, {30, 80, 130}, {60, 120, 170})
                 : uniform_bgr(rng, {30, 170, 120}, {80, 225, 200});
  return leaf;
}

constexpr EnumNames<BallLayout, 4> kBallLayouts{{{BallLayout::scattered, "scattered"},
                                                 {BallLayout::along_net, "along_net"},
                                                 {BallLayout::along_fence, "along_fence"},
                                                 {BallLayout::net_posts, "net_posts"}}};

}  // namespace

std::string_view ball_layout_name(BallLayout layout) {
  return enum_name(kBallLayouts, layout);
}

void CourtScenarioOptions::validate() const {
  if (ball_count) {
    require(
        *ball_count >= 0 && *ball_count <= kMaxBalls, "balls",
        "must be in [0, " + std::to_string(kMaxBalls) + "], got " + std::to_string(*ball_count));
  }
  require(std::isfinite(cluster_share) && cluster_share >= 0.0 && cluster_share <= 1.0,
          "cluster_share", "must be in [0, 1]");
  require(std::isfinite(worn_share_max) && worn_share_max >= 0.0 && worn_share_max <= 1.0,
          "worn_share_max", "must be in [0, 1]");
  ImageEffects effects;
  effects.noise_sigma = noise_sigma;
  if (brightness_gain) effects.brightness_gain = *brightness_gain;
  effects.jpeg_quality = jpeg_quality;
  effects.motion_blur_px = motion_blur_px;
  effects.validate();
  obstacles.validate();
}

std::vector<Vec3> reference_ball_positions(const TennisCourtSpec& court) {
  const double w = court.line_width_m, r = kReferenceBallRadiusM;
  const double baseline = court.length_m / 2.0 - w / 2.0;
  const double service = court.service_line_from_net_m - w / 2.0;
  const double singles = court.singles_width_m / 2.0 - w / 2.0;
  const double doubles = court.doubles_width_m / 2.0 - w / 2.0;
  return {{baseline, singles, r},  {baseline, -singles, r}, {-baseline, -singles, r},
          {-baseline, singles, r}, {service, singles, r},   {service, -singles, r},
          {-service, -singles, r}, {-service, singles, r},  {service, 0.0, r},
          {-service, 0.0, r},      {0.0, doubles, r},       {0.0, -doubles, r}};
}

CourtScene make_court_scene(const TennisCourtSpec& court, const CourtScenarioOptions& options,
                            std::uint64_t seed) {
  court.validate();
  options.validate();
  std::mt19937_64 rng(seed);
  CourtScene scene;
  scene.robot.front_marker_bgr = court.robot_front_marker_bgr;
  scene.robot.back_marker_bgr = court.robot_back_marker_bgr;
  const std::vector<Vec3> references = reference_ball_positions(court);

  // The robot somewhere on the court, clear of the reference balls and of the net (its centre at
  // least its half-diagonal from the net's footprint, whatever its heading).
  const GroundRect on_court = court.court_rect();
  const std::optional<FloorBox> net = net_footprint(court);
  const auto clear = [&](const RobotBox& robot) {
    for (const Vec3& p : references) {
      if (footprint_distance(footprint(robot), p.head<2>()) < 0.4) return false;
    }
    const double half_diagonal = std::hypot(robot.length_m, robot.width_m) / 2.0;
    return !net || footprint_distance(*net, robot.pose.position) >= half_diagonal + kBallGapM;
  };
  do {
    scene.robot.pose = {uniform_in(rng, on_court, 1.0), uniform(rng, -kPi, kPi)};
  } while (!clear(scene.robot));  // a few draws: the references and the net are small

  Placement placement(scene.robot, net);
  for (size_t i = 0; i < references.size(); ++i) {
    scene.balls.push_back({ObjectKind::reference_ball, static_cast<int>(i), references[i],
                           kReferenceBallRadiusM, court.reference_ball_bgr});
    placement.add(scene.balls.back());
  }

  const int count = options.ball_count ? *options.ball_count : uniform_int(rng, 20, 60);
  const double r = kTennisBallRadiusM;
  int id = 0;
  const auto add_ball = [&](const Vec2& xy) {
    scene.balls.push_back(tennis_ball(id++, xy));
    placement.add(scene.balls.back());
  };

  // Clusters of 2-4 touching balls (a quarter of all balls by default).
  const int clustered = static_cast<int>(count * options.cluster_share);
  while (id < clustered) {
    const int size = std::min(uniform_int(rng, 2, 4), clustered - id);
    const int first = static_cast<int>(scene.balls.size());
    add_ball(place(rng, placement, r, [&](auto& g) { return uniform_in(g, on_court, 0.5); }));
    for (int k = 1; k < size; ++k) {
      add_ball(place(rng, placement, r, [&](auto& g) {
        const int member = uniform_int(g, first, static_cast<int>(scene.balls.size()) - 1);
        const double a = uniform(g, -kPi, kPi);
        return Vec2(scene.balls[static_cast<size_t>(member)].center_in_field.head<2>() +
                    (2.0 * r + kBallGapM) * Vec2(std::cos(a), std::sin(a)));
      }));
    }
  }

  // Up to four balls right beside the robot: hidden from the cameras on the robot's far side.
  const RobotBox& robot = scene.robot;
  for (int k = 0; k < 4 && id < count; ++k) {
    add_ball(place(rng, placement, r, [&](auto& g) {
      const double along = uniform(g, -0.5, 0.5), gap = r + uniform(g, 0.005, 0.3);
      const bool long_side = uniform_int(g, 0, 1) == 1;
      const double side = uniform_int(g, 0, 1) == 1 ? 1.0 : -1.0;
      const Vec2 in_robot = long_side
                                ? Vec2(along * robot.length_m, side * (robot.width_m / 2 + gap))
                                : Vec2(side * (robot.length_m / 2 + gap), along * robot.width_m);
      return Vec2(robot.pose.field_from_robot() * in_robot);
    }));
  }

  // The rest as the layout puts them; scattered: mostly on the court, some rolled into the
  // run-off area.
  while (id < count) {
    if (options.layout != BallLayout::scattered) {
      add_ball(
          place(rng, placement, r, [&](auto& g) { return laid_out(g, court, options.layout); }));
      continue;
    }
    const bool on_run_off = uniform(rng, 0.0, 1.0) < 0.15;
    const GroundRect area = on_run_off ? court.surround_rect() : on_court;
    add_ball(place(rng, placement, r, [&](auto& g) { return uniform_in(g, area, 0.3); }));
  }

  // Drawn after the balls, so that the balls of a seed do not depend on the weather.
  const LightCondition light =
      options.light ? *options.light : static_cast<LightCondition>(uniform_int(rng, 0, 2));
  scene.lighting = random_lighting(rng, court, options.shadow, light);
  scene.effects.brightness_gain = options.brightness_gain             ? *options.brightness_gain
                                  : light == LightCondition::overcast ? uniform(rng, 0.65, 0.9)
                                  : light == LightCondition::indoor   ? uniform(rng, 0.6, 0.85)
                                                                      : uniform(rng, 0.8, 1.2);
  // Lamps of 3000-4000 K under a white balance set for daylight: red up, blue down.
  if (light == LightCondition::indoor)
    scene.effects.channel_gain = {uniform(rng, 0.78, 0.92), 1.0, uniform(rng, 1.03, 1.15)};
  const double worn_share = uniform(rng, 0.0, options.worn_share_max);
  for (SceneSphere& ball : scene.balls)
    if (ball.kind == ObjectKind::tennis_ball && uniform(rng, 0.0, 1.0) < worn_share)
      ball.bgr = worn_colour(ball.bgr, uniform(rng, 0.25, 0.55));
  if (options.distractors && uniform_int(rng, 0, 1) == 1) {
    const int leaves = uniform_int(rng, 3, 12);
    for (int k = 0; k < leaves; ++k) scene.leaves.push_back(random_leaf(rng, court));
  }
  if (options.distractors && uniform_int(rng, 0, 3) == 0) {
    FloorBottle bottle;
    bottle.radius_m = uniform(rng, 0.032, 0.04);
    bottle.height_m = uniform(rng, 0.2, 0.26);
    bottle.center_in_field = place(rng, placement, bottle.radius_m, [&](auto& g) {
      return uniform_in(g, court.surround_rect(), 0.3);
    });
    bottle.bgr = uniform_bgr(rng, {30, 190, 150}, {70, 235, 210});
    scene.bottles.push_back(bottle);
  }
  scene.effects.noise_sigma = options.noise_sigma;
  scene.effects.jpeg_quality = options.jpeg_quality;
  if (options.motion_blur_px > 0.0) {
    scene.effects.motion_blur_px = options.motion_blur_px;
    scene.effects.motion_blur_deg = uniform(rng, 0.0, 180.0);
  }
  add_obstacles(scene, court, options.obstacles, seed);
  scene.validate();
  return scene;
}

}  // namespace ballsight::sim
