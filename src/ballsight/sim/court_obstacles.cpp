#include "ballsight/sim/court_obstacles.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/sim/seeding.hpp"

namespace ballsight::sim {
namespace {

constexpr std::uint64_t kStream = 7;  // of the scene's seed
constexpr double kNetGapM = 1.2, kFenceGapM = 1.2, kRobotGapM = 1.5, kApartM = 2.0;

// Clothes and bags: dark red, black, light grey, navy, a tennis bag's red and white.
const std::array<cv::Vec3b, 5> kCloth{
    {{40, 40, 150}, {35, 35, 35}, {190, 190, 185}, {90, 45, 30}, {50, 60, 200}}};

bool obstacle_clear(const CourtScene& scene, const TennisCourtSpec& court, const CourtObstacle& o,
                    double ball_gap_m) {
  const Vec2& p = o.pose.position;
  const double reach = o.half_size.norm();
  if (std::abs(p.x()) < kNetGapM + reach ||
      std::abs(p.x()) > court.surround_length_m / 2.0 - kFenceGapM - reach ||
      std::abs(p.y()) > court.surround_width_m / 2.0 - kFenceGapM - reach) {
    return false;
  }
  for (const SceneSphere& b : scene.balls)
    if (o.floor_distance(b.center_in_field.head<2>()) < ball_gap_m) return false;
  if ((p - scene.robot.pose.position).norm() < kRobotGapM + reach) return false;
  for (const CourtObstacle& other : scene.obstacles)
    if ((p - other.pose.position).norm() < kApartM) return false;
  return true;
}

CourtObstacle draw_obstacle(std::mt19937_64& rng, const TennisCourtSpec& court, ObstacleKind kind) {
  CourtObstacle o;
  o.kind = kind;
  const double half_length = court.surround_length_m / 2.0,
               half_width = court.surround_width_m / 2.0;
  o.pose = {Vec2(uniform(rng, -half_length, half_length), uniform(rng, -half_width, half_width)),
            rad_from_deg(uniform(rng, -180.0, 180.0))};
  o.bgr =
      kCloth[static_cast<std::size_t>(uniform_int(rng, 0, static_cast<int>(kCloth.size()) - 1))];
  if (kind == ObstacleKind::person) {
    o.half_size = Vec2::Constant(uniform(rng, 0.2, 0.25));
    o.height_m = uniform(rng, 1.6, 1.9);
  } else {
    o.half_size = Vec2(uniform(rng, 0.35, 0.45), uniform(rng, 0.15, 0.2));
    o.height_m = uniform(rng, 0.25, 0.35);
  }
  return o;
}

}  // namespace

void ObstacleOptions::validate() const {
  for (const auto& [name, n] : {std::pair{"people", people}, {"bags", bags}, {"walkers", walkers}})
    require(n >= 0 && n <= 4, name, "must be in [0, 4], got " + std::to_string(n));
  require(std::isfinite(ball_gap_m) && ball_gap_m >= 0.0 && ball_gap_m <= 2.0, "ball_gap_m",
          "must be in [0, 2] m");
}

ObstacleOptions parse_obstacles(std::string_view list, const std::string& option) {
  ObstacleOptions o;
  if (list == "none") return o;
  while (!list.empty()) {
    const std::size_t comma = list.find(',');
    const std::string_view item = list.substr(0, comma);
    if (item == "person") {
      ++o.people;
    } else if (item == "bag") {
      ++o.bags;
    } else if (item == "walker") {
      ++o.walkers;
    } else {
      throw InputError(option + ": unknown obstacle '" + std::string(item) +
                       "' (person, bag, walker, or none)");
    }
    list = comma == std::string_view::npos ? std::string_view() : list.substr(comma + 1);
  }
  try {
    o.validate();
  } catch (const InputError& e) {
    throw InputError(option + ": " + e.what());
  }
  return o;
}

void add_obstacles(CourtScene& scene, const TennisCourtSpec& court, const ObstacleOptions& options,
                   std::uint64_t seed) {
  options.validate();
  std::mt19937_64 rng(derive_seed(seed, kStream));
  const auto place = [&](ObstacleKind kind) {
    for (int attempt = 0; attempt < 20000; ++attempt) {
      const CourtObstacle o = draw_obstacle(rng, court, kind);
      if (obstacle_clear(scene, court, o, options.ball_gap_m)) return o;
    }
    throw std::logic_error("court scenario: no free place for an obstacle");
  };
  for (int k = 0; k < options.people; ++k) scene.obstacles.push_back(place(ObstacleKind::person));
  for (int k = 0; k < options.bags; ++k) scene.obstacles.push_back(place(ObstacleKind::bag));
  for (int k = 0; k < options.walkers; ++k) {
    // Across the court from where it stands, at the same distance from the net: it passes the
    // balls and the robot's ways, and turns back short of the fence.
    CourtObstacle o = place(ObstacleKind::person);
    const double turn_y = court.surround_width_m / 2.0 - kFenceGapM - o.half_size.x();
    o.walk_to = Vec2(o.pose.position.x(), o.pose.position.y() > 0.0 ? -turn_y : turn_y);
    o.walk_mps = 0.3;
    scene.obstacles.push_back(o);
  }
}

}  // namespace ballsight::sim
