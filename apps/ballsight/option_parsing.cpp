#include "option_parsing.hpp"

#include <charconv>
#include <cmath>
#include <sstream>

#include "ballsight/core/error.hpp"

namespace ballsight::app {

std::vector<double> parse_numbers(const std::string& text, std::size_t count,
                                  const std::string& option, const std::string& what) {
  std::istringstream in(text);
  std::vector<double> numbers;
  bool ok = true;
  for (std::size_t i = 0; i < count && ok; ++i) {
    double value = 0.0;
    char comma = ',';
    if (i > 0) in >> comma;
    in >> value;
    ok = in && comma == ',' && std::isfinite(value);
    numbers.push_back(value);
  }
  require(ok && (in >> std::ws).eof(), option, "expected " + what + ", got '" + text + "'");
  return numbers;
}

CLI::Option* add_seed_option(CLI::App& command, std::uint64_t& seed, const std::string& help) {
  const CLI::Validator digits(
      [](std::string& text) -> std::string {
        std::uint64_t value = 0;
        const char* end = text.data() + text.size();
        const auto [stop, error] = std::from_chars(text.data(), end, value);
        if (!text.empty() && error == std::errc() && stop == end) return {};
        return "expected an integer in [0, 2^64), got '" + text + "'";
      },
      "UINT");
  return command.add_option("--seed", seed, help)->check(digits)->capture_default_str();
}

std::optional<sim::LightCondition> parse_light(const std::string& name) {
  if (name == "random") return std::nullopt;
  if (const auto light = sim::light_condition_named(name)) return light;
  throw InputError("--light: unknown light '" + name +
                   "'; expected random, sun, hard_shadow, overcast or indoor");
}

void add_court_look_options(CLI::App& command, sim::TennisCourtSpec& court,
                            sim::CourtScenarioOptions& scenario) {
  command.add_option_function<std::string>(
      "--light", [&scenario](const std::string& name) { scenario.light = parse_light(name); },
      "sun, hard_shadow, overcast, indoor (a hall's warm lamps), or random: one of the first "
      "three per scene (default)");
  command.add_option_function<std::string>(
      "--surface",
      [&court](const std::string& name) {
        const auto surface = sim::court_surface_named(name);
        if (!surface)
          throw InputError("--surface: unknown surface '" + name +
                           "'; expected green, blue, red, concrete or wood");
        sim::set_court_surface(court, *surface);
      },
      "The court's surface: green (default), blue, red, concrete or wood");
}

void add_court_scene_options(CLI::App& command, int& scenes, sim::CourtRigOptions& rig,
                             sim::TennisCourtSpec& court, sim::CourtScenarioOptions& scenario) {
  command.add_option("--scenes", scenes, "Number of scenes [1, 1000]")->capture_default_str();
  command.add_option("--width", rig.width, "Camera image width, px")->capture_default_str();
  command.add_option("--height", rig.height, "Camera image height, px")->capture_default_str();
  command.add_flag("--distractors", scenario.distractors,
                   "Fallen leaves and a water bottle of a ball's colour on some scenes");
  command.add_option_function<std::string>(
      "--camera-height-m",
      [&rig](const std::string& text) {
        const std::vector<double> range =
            parse_numbers(text, 2, "--camera-height-m", "MIN,MAX in metres");
        require(range[0] >= 0.2 && range[1] >= range[0] && range[1] <= 30.0, "--camera-height-m",
                "MIN must be at least 0.2 m and MAX within [MIN, 30] m");
        rig.pole_height_min_m = range[0];
        rig.pole_height_max_m = range[1];
      },
      "The cameras' heights, each drawn in MIN,MAX (default 4,6: corner masts; 0.3,0.5: a "
      "robot's view across the court)");
  command
      .add_option("--jpeg-quality", scenario.jpeg_quality,
                  "Every frame saved as a JPEG of this quality and decoded (0: none)")
      ->check(CLI::Range(0, 100))
      ->capture_default_str();
  command
      .add_option("--motion-blur-px", scenario.motion_blur_px,
                  "Every frame smeared by this many pixels, in a direction drawn per scene")
      ->check(CLI::Range(0.0, 64.0))
      ->capture_default_str();
  add_court_look_options(command, court, scenario);
}

Vec2 parse_pixel_pair(const std::string& text, const std::string& option) {
  const std::vector<double> xy = parse_numbers(text, 2, option, "two numbers X,Y in pixels");
  return {xy[0], xy[1]};
}

Eigen::Vector2i parse_image_size(const std::string& text, const std::string& option) {
  std::istringstream in(text);
  int width = 0, height = 0;
  char times = 0;
  in >> width >> times >> height;
  require(in && times == 'x' && (in >> std::ws).eof() && width > 0 && height > 0, option,
          "expected a size WxH in pixels such as 640x480, got '" + text + "'");
  return {width, height};
}

cv::Vec3b parse_bgr(const std::string& text, const std::string& option) {
  const std::vector<double> bgr = parse_numbers(text, 3, option, "B,G,R in 0..255");
  for (double c : bgr) require(c >= 0 && c <= 255, option, "channels must be in 0..255");
  return {static_cast<uchar>(bgr[0]), static_cast<uchar>(bgr[1]), static_cast<uchar>(bgr[2])};
}

}  // namespace ballsight::app
