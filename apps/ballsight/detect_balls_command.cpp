// `ballsight detect balls` and `ballsight colours learn`: tennis balls in any photo, with the
// default colour model or one learned from a few clicked ball pixels.
#include <iostream>
#include <memory>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "ballsight/camera/image_file.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/text_format.hpp"
#include "ballsight/detect/ball_colour_learning.hpp"
#include "ballsight/detect/photo_ball_fit.hpp"
#include "ballsight/detect/photo_balls.hpp"
#include "commands.hpp"
#include "option_parsing.hpp"

namespace ballsight::app {

namespace {

struct DetectArgs {
  std::string image;
  std::optional<std::string> colours;
  std::optional<std::string> detector;
  std::optional<std::string> plot;
  bool json = false;
  PhotoBallOptions options = shipped_photo_ball_options();
};

cv::Mat plot_balls(const cv::Mat& bgr, const std::vector<PhotoBall>& balls) {
  cv::Mat plot = bgr.clone();
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const PhotoBall& b = balls[i];
    const cv::Point center(static_cast<int>(std::lround(b.center_px.x() * 16.0)),
                           static_cast<int>(std::lround(b.center_px.y() * 16.0)));
    const int radius = static_cast<int>(std::lround(b.radius_px * 16.0));
    cv::circle(plot, center, radius, {255, 0, 255}, 2, cv::LINE_AA, 4);
    cv::circle(plot, center, 16, {255, 0, 255}, -1, cv::LINE_AA, 4);
    const std::string label = std::to_string(i + 1) + " " + fixed(b.score, 2);
    cv::putText(plot, label,
                cv::Point(static_cast<int>(b.center_px.x() + b.radius_px * 0.7) + 2,
                          static_cast<int>(b.center_px.y() - b.radius_px * 0.7) - 2),
                cv::FONT_HERSHEY_SIMPLEX, 0.4, {255, 0, 255}, 1, cv::LINE_AA);
  }
  return plot;
}

// Whether any pixel's channels differ (a greyscale photo decoded as BGR has none).
bool has_colour(const cv::Mat& bgr) {
  for (int y = 0; y < bgr.rows; ++y) {
    const auto* row = bgr.ptr<cv::Vec3b>(y);
    for (int x = 0; x < bgr.cols; ++x)
      if (row[x][0] != row[x][1] || row[x][1] != row[x][2]) return true;
  }
  return false;
}

void run_detect(DetectArgs& args) {
  if (args.detector) {  // its colours, contrast split and threshold; the radii as given
    PhotoBallOptions fitted = read_photo_ball_options(*args.detector);
    fitted.circles.min_radius_px = args.options.circles.min_radius_px;
    fitted.circles.max_radius_px = args.options.circles.max_radius_px;
    args.options = fitted;
  }
  if (args.colours) args.options.colours = read_ball_colours(*args.colours);
  const cv::Mat image = read_image_bgr(args.image);
  require(has_colour(image), args.image,
          "a greyscale image (no pixel has colour): balls are found by their colour");
  PhotoBallDetector detector(args.options);
  const std::vector<PhotoBall> balls = detector.detect(image);
  if (args.plot) write_png_atomic(*args.plot, plot_balls(image, balls));
  if (args.json) {
    nlohmann::json list = nlohmann::json::array();
    for (const PhotoBall& b : balls)
      list.push_back({{"x_px", b.center_px.x()},
                      {"y_px", b.center_px.y()},
                      {"radius_px", b.radius_px},
                      {"score", b.score}});
    std::cout << nlohmann::json{{"balls", list}}.dump(2) << "\n";
    return;
  }
  std::cout << balls.size() << " ball" << (balls.size() == 1 ? "" : "s") << " in " << args.image
            << " (" << image.cols << "x" << image.rows << ")\n";
  for (std::size_t i = 0; i < balls.size(); ++i)
    std::cout << "  " << i + 1 << ": centre "
              << fixed_pair(balls[i].center_px.x(), balls[i].center_px.y(), 1) << " px, radius "
              << fixed(balls[i].radius_px, 1) << " px, score " << fixed(balls[i].score, 2) << "\n";
}

void add_detect_balls_command(CLI::App& detect) {
  auto args = std::make_shared<DetectArgs>();
  CLI::App* cmd = detect.add_subcommand(
      "balls",
      "Every tennis ball in a photo (a court camera's frame or a robot's view ahead): centre and "
      "radius in pixels, touching balls apart, balls cut by the border with their whole circle");
  cmd->add_option("--image", args->image, "The photo (PNG, JPEG)")->required();
  cmd->add_option("--colours", args->colours,
                  "A colour model learned with `colours learn` (default: optic yellow tennis "
                  "balls, in light and in shade, and stage orange ones)")
      ->type_name("FILE");
  cmd->add_option("--detector", args->detector,
                  "Settings written by `detect fit` (colour model, contrast split, score "
                  "threshold; default: built in)")
      ->type_name("FILE")
      ->excludes("--colours");
  cmd->add_option("--min-radius-px", args->options.circles.min_radius_px,
                  "Smallest ball radius looked for")
      ->capture_default_str();
  cmd->add_option("--max-radius-px", args->options.circles.max_radius_px,
                  "Largest ball radius looked for")
      ->capture_default_str();
  cmd->add_option("--min-score", args->options.circles.min_score,
                  "Balls scoring less (0-1: outline seen, disc full, ring around empty) are left "
                  "out")
      ->capture_default_str()
      ->excludes("--detector");
  cmd->add_flag("--json", args->json,
                "Print JSON: {\"balls\": [{\"x_px\", \"y_px\", \"radius_px\", \"score\"}]}");
  cmd->add_option("--plot", args->plot, "Also write a PNG with the balls drawn")->type_name("PNG");
  cmd->callback([args] { run_detect(*args); });
}

struct LearnArgs {
  std::string image;
  std::string at;
  std::string out;
};

std::vector<Vec2> parse_clicks(const std::string& text) {
  std::vector<Vec2> clicks;
  std::istringstream in(text);
  std::string item;
  while (std::getline(in, item, ';'))
    clicks.push_back(
        parse_pixel_pair(item, "--at (click " + std::to_string(clicks.size() + 1) + ")"));
  require(!clicks.empty(), "--at", "expected at least one click X,Y");
  return clicks;
}

void run_learn(const LearnArgs& args) {
  const std::vector<Vec2> clicks = parse_clicks(args.at);
  const cv::Mat image = read_image_bgr(args.image);
  BallColours colours;
  try {
    colours = learn_ball_colours(image, clicks);
  } catch (const InputError& e) {
    throw InputError(args.image + ": " + e.what());
  }
  write_ball_colours(args.out, colours);
  std::cout << colours.colours.size() << " colour" << (colours.colours.size() == 1 ? "" : "s")
            << " from " << clicks.size() << " click" << (clicks.size() == 1 ? "" : "s") << " -> "
            << args.out << "\n";
  for (const BallColour& c : colours.colours)
    std::cout << "  " << c.name << ": seed hue " << fixed(c.seed.hue_min_deg, 0) << "-"
              << fixed(c.seed.hue_max_deg, 0)
              << " deg, saturation >= " << fixed(c.seed.min_saturation, 2)
              << ", value >= " << fixed(c.seed.min_value, 0) << "\n";
}

void add_colours_learn_command(CLI::App& colours) {
  auto args = std::make_shared<LearnArgs>();
  CLI::App* cmd = colours.add_subcommand(
      "learn", "Learn a ball colour model from a few clicked ball pixels of a photo");
  cmd->add_option("--image", args->image, "The photo (PNG, JPEG)")->required();
  cmd->add_option("--at", args->at,
                  "Clicked ball pixels X,Y[;X,Y...] (quote it in a shell: ';' separates clicks)")
      ->required();
  cmd->add_option("--out", args->out, "Colour model file to write (JSON)")->required();
  cmd->callback([args] { run_learn(*args); });
}

}  // namespace

void add_detect_commands(CLI::App& app) {
  CLI::App* detect = app.add_subcommand("detect", "Find objects in photos");
  detect->require_subcommand(1);
  add_detect_balls_command(*detect);
  add_detect_fit_command(*detect);
  add_detect_patches_command(*detect);
  CLI::App* colours = app.add_subcommand("colours", "Colour models of the objects detected");
  colours->require_subcommand(1);
  add_colours_learn_command(*colours);
}

}  // namespace ballsight::app
