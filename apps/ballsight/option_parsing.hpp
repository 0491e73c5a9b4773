#pragma once
// Parsing of option values the library has no type for; errors name the option.

#include <CLI/CLI.hpp>
#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ballsight/core/geometry.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "ballsight/sim/court_scenario.hpp"
#include "ballsight/sim/tennis_court.hpp"

namespace ballsight::app {

/// The help of `--mirror` (sim omni, eval omni).
inline constexpr const char* kMirrorHelp =
    "The rig's mirror: unified (the central model ballsight fits), sphere, cone or table (a "
    "compound free profile; non-central, ray-traced; defaults in docs/sim-omni.md)";

/// "A,B,C" -> exactly `count` finite comma-separated numbers; throws InputError naming `option`
/// and saying what was expected (`what`, e.g. "X,Y,THETA_DEG: robot position in cm and heading").
std::vector<double> parse_numbers(const std::string& text, std::size_t count,
                                  const std::string& option, const std::string& what);

/// Adds `--seed` to `command`: an integer in [0, 2^64), checked as text (CLI11 alone would wrap
/// "-5" into a huge seed).
CLI::Option* add_seed_option(CLI::App& command, std::uint64_t& seed, const std::string& help);

/// `--light NAME`: random (nullopt) or a sim::LightCondition; throws InputError otherwise.
std::optional<sim::LightCondition> parse_light(const std::string& name);

/// Adds `--light` (sim::CourtScenarioOptions::light) and `--surface` (sim::CourtSurface) to
/// `command`; `court` and `scenario` must outlive it.
void add_court_look_options(CLI::App& command, sim::TennisCourtSpec& court,
                            sim::CourtScenarioOptions& scenario);

/// Adds the simulated court's `--scenes`, `--width`, `--height`, `--distractors`,
/// `--camera-height-m`, `--jpeg-quality` and `--motion-blur-px`, and the court look options above
/// (eval court, eval tennis-sim).
void add_court_scene_options(CLI::App& command, int& scenes, sim::CourtRigOptions& rig,
                             sim::TennisCourtSpec& court, sim::CourtScenarioOptions& scenario);

/// "X,Y" -> two finite numbers; throws InputError naming `option`.
Vec2 parse_pixel_pair(const std::string& text, const std::string& option);

/// "WxH" -> two positive integers; throws InputError naming `option`.
Eigen::Vector2i parse_image_size(const std::string& text, const std::string& option);

/// "B,G,R" -> a colour, each channel in 0..255; throws InputError naming `option`.
cv::Vec3b parse_bgr(const std::string& text, const std::string& option);

}  // namespace ballsight::app
