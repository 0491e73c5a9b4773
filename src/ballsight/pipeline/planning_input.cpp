#include "ballsight/pipeline/planning_input.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/csv_fields.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/core/json_fields.hpp"
#include "ballsight/core/text_format.hpp"

namespace ballsight {
namespace {

// The cameras place a ball far from all of them a few cm off (a ball against the fence near a
// mast is seen from 35 m and more): one seen this little beyond the fence lies against it.
constexpr double kBeyondFenceM = 0.25;
// The planner goes round the 16 obstacles nearest the robot (ObstacleDetours' limit), each at
// most 5 m across.
constexpr std::size_t kMaxObstacles = 16;
constexpr double kMaxObstacleRadiusM = 5.0;

}  // namespace

std::vector<ObstacleDisc> obstacle_discs(const WorldModel& world, const Pose2D& robot) {
  std::vector<ObstacleDisc> discs;
  for (const FloorObstacle& o : world.obstacles) {
    if (on_robot_body(robot, o.center_m)) continue;
    discs.push_back({o.center_m, std::min(o.radius_m, kMaxObstacleRadiusM)});
  }
  std::sort(discs.begin(), discs.end(), [&](const ObstacleDisc& a, const ObstacleDisc& b) {
    return (a.center_m - robot.position).norm() < (b.center_m - robot.position).norm();
  });
  if (discs.size() > kMaxObstacles) discs.resize(kMaxObstacles);
  return discs;
}

double obstacle_keep_m(const SiteRobot& robot) {
  constexpr double kBoxHalfLengthM = 0.30, kBoxHalfWidthM = 0.225, kRoomM = 0.10;
  return std::hypot(std::max(kBoxHalfLengthM, robot.collector_x_m),
                    std::max(kBoxHalfWidthM, robot.collector_width_m / 2.0)) +
         kRoomM;
}

PlanningProblem site_planning_problem(const Site& site, const Pose2D& robot,
                                      std::vector<Vec2> balls) {
  PlanningProblem problem;
  problem.court = drivable_court(site.court);
  const std::optional<CourtNet>& net = problem.court->net;
  require(!(net && std::abs(robot.position.x()) < net->clearance_m &&
            std::abs(robot.position.y()) < net->half_length_m),
          "robot pose",
          fixed_pair(robot.position.x(), robot.position.y(), 3) + " is inside the net");
  const Vec2 forward(std::cos(robot.heading_rad), std::sin(robot.heading_rad));
  // Beyond a post but within the room the route keeps round it (the robot drove round it there):
  // the route starts from the nearest point outside that room.
  problem.robot = {
      problem.court->outside_net_zone(robot.position + site.robot.collector_x_m * forward),
      robot.heading_rad};
  const Vec2 inside = Vec2::Constant(site.ball_radius_m);
  for (Vec2& b : balls) {
    const Vec2 against =
        b.cwiseMax(problem.court->area_min_m + inside).cwiseMin(problem.court->area_max_m - inside);
    if ((against - b).norm() <= kBeyondFenceM) b = against;
  }
  problem.balls = std::move(balls);
  problem.limits = {site.robot.max_speed_mps, site.robot.turn_rate_dps};
  problem.collector_width_m = site.robot.collector_width_m;
  problem.ball_radius_m = site.ball_radius_m;
  return problem;
}

WorldBalls parse_world_balls(std::string_view text, const std::string& source) {
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  require(!j.is_discarded(), source, "not valid JSON");
  require(j.is_object(), source, "expected a world model object (court run --json)");
  const auto balls = j.find("balls");
  require(balls != j.end() && balls->is_array(), source, "key 'balls' (a list) missing");
  WorldBalls out;
  for (std::size_t i = 0; i < balls->size(); ++i) {
    const std::string where = source + ": balls[" + std::to_string(i) + "]";
    out.balls.emplace_back(json_number((*balls)[i], "x_m", where),
                           json_number((*balls)[i], "y_m", where));
  }
  if (const auto robot = j.find("robot"); robot != j.end() && !robot->is_null()) {
    const std::string where = source + ": robot";
    out.robot = Pose2D{Vec2(json_number(*robot, "x_m", where), json_number(*robot, "y_m", where)),
                       rad_from_deg(json_number(*robot, "heading_deg", where))};
  }
  return out;
}

WorldBalls read_world_balls(const std::filesystem::path& file) {
  return parse_world_balls(read_file(file, kMaxDocumentBytes), file.string());
}

std::vector<Vec2> parse_ball_csv(std::string_view text, const std::string& source) {
  std::vector<Vec2> balls;
  std::size_t line_number = 0;
  bool header = false;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    const std::string_view line = text.substr(0, end);
    text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
    ++line_number;
    const std::string at = source + ":" + std::to_string(line_number);
    if (trim_blanks(line).empty()) continue;
    const std::vector<CsvField> fields = split_csv_fields(line);
    if (!header) {
      require(fields.size() == 2 && fields[0].text == "x_m" && fields[1].text == "y_m", at,
              "expected the header x_m,y_m");
      header = true;
      continue;
    }
    require(fields.size() == 2, at,
            "expected two values x_m,y_m, got " + std::to_string(fields.size()));
    double xy[2];
    for (int k = 0; k < 2; ++k) {
      const std::string_view t = fields[static_cast<std::size_t>(k)].text;
      const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), xy[k]);
      require(ec == std::errc() && ptr == t.data() + t.size() && std::isfinite(xy[k]),
              at + ":" + std::to_string(fields[static_cast<std::size_t>(k)].column),
              std::string(k == 0 ? "x_m" : "y_m") + ": expected a finite number, got '" +
                  std::string(t) + "'");
    }
    balls.emplace_back(xy[0], xy[1]);
  }
  require(header, source, "empty: expected the header x_m,y_m");
  return balls;
}

std::vector<Vec2> read_ball_csv(const std::filesystem::path& file) {
  return parse_ball_csv(read_file(file, kMaxDocumentBytes), file.string());
}

}  // namespace ballsight
