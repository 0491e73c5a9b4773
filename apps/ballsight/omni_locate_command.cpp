// `ballsight omni locate`: the run time on one image: find the ball, place it on the field.
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "ballsight/camera/ground_map_io.hpp"
#include "ballsight/camera/image_file.hpp"
#include "ballsight/core/angle.hpp"
#include "ballsight/core/conventions.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/pipeline/omni_pipelines.hpp"
#include "commands.hpp"
#include "option_parsing.hpp"

namespace ballsight::app {

namespace {

struct LocateArgs {
  std::string lut;
  std::string image;
  std::string robot;
  std::string ball_bgr = "0,110,255";
  double ball_radius_cm = 11.0;
  bool json = false;
};

void run_locate(const LocateArgs& args) {
  const std::vector<double> robot =
      parse_numbers(args.robot, 3, "--robot", "X,Y,THETA_DEG: robot position in cm and heading");
  const cv::Vec3b ball_bgr = parse_bgr(args.ball_bgr, "--ball-bgr");
  const GroundMap map = load_ground_map(args.lut);
  const cv::Mat frame = read_image_bgr(args.image, cv::Size(map.width(), map.height()));
  const Pose2D robot_cm{{robot[0], robot[1]}, rad_from_deg(robot[2])};
  BallOnFloor ball;
  ball.radius_cm = args.ball_radius_cm;
  const BallsightOmniPipeline pipeline(yuv_range_around(ball_bgr), map, ball);
  const std::optional<Vec2> p_in_robot = pipeline.locate_in_robot_cm(frame);
  if (args.json) {
    nlohmann::json out = {{"found", p_in_robot.has_value()}};
    if (p_in_robot) {
      const Vec2 field = field_from_robot_point(robot_cm, *p_in_robot);
      out["ball_in_robot_cm"] = {p_in_robot->x(), p_in_robot->y()};
      out["ball_in_field_cm"] = {field.x(), field.y()};
      out["distance_cm"] = p_in_robot->norm();
      out["bearing_deg"] = polar_from_cartesian(*p_in_robot).theta_deg;
    }
    std::cout << out.dump(2) << "\n";
    return;
  }
  if (!p_in_robot) {
    std::cout << "no ball found in " << args.image << "\n";
    return;
  }
  const Vec2 field = field_from_robot_point(robot_cm, *p_in_robot);
  char line[200];
  std::snprintf(
      line, sizeof line,
      "ball at (%.1f, %.1f) cm on the field; %.1f cm from the robot at bearing %.1f deg\n",
      field.x(), field.y(), p_in_robot->norm(),
      wrap_deg_180(polar_from_cartesian(*p_in_robot).theta_deg));
  std::cout << line;
}

}  // namespace

void add_omni_locate_command(CLI::App& omni) {
  auto args = std::make_shared<LocateArgs>();
  CLI::App* cmd = omni.add_subcommand(
      "locate",
      "Find the ball in an omni image and place it on the field through a lookup table (omni fit "
      "--out): whole-blob silhouette, corrected for the ball's radius");
  cmd->add_option("--lut", args->lut, "Lookup table (ballsight ground map)")->required();
  cmd->add_option("--image", args->image, "Omni image (PNG, JPEG) of the table's size")->required();
  cmd->add_option("--robot", args->robot, "Robot pose X,Y,THETA_DEG: field cm and heading")
      ->required()
      ->type_name("X,Y,THETA_DEG");
  cmd->add_option("--ball-bgr", args->ball_bgr, "Ball colour B,G,R (thresholds around it in YUV)")
      ->capture_default_str();
  cmd->add_option("--ball-radius-cm", args->ball_radius_cm, "Ball radius in cm")
      ->capture_default_str();
  cmd->add_flag("--json", args->json, "Print JSON");
  cmd->callback([args] { run_locate(*args); });
}

}  // namespace ballsight::app
