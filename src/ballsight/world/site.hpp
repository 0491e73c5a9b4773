#pragma once
// The site file: what a fixed-camera installation around a tennis court needs to know (the
// tennis-ball-collecting-robot report, chapters 6.2 and 7.4): the court, the cameras (where their
// images come from, their calibration files, roughly where they stand), the reference balls'
// field coordinates, the colours of the balls and the robot's markers, and the robot's
// collector width. Written by hand in YAML; schema and example in docs/site-file.md.

#include <cstdint>
#include <filesystem>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ballsight/core/geometry.hpp"
#include "ballsight/core/site_court.hpp"

namespace ballsight {

/// Where a camera's images come from.
struct CameraSource {
  enum class Kind { file, folder, device, url };
  Kind kind = Kind::file;
  std::filesystem::path path;  // file or folder, resolved against the site file's folder
  int device = 0;              // video device index
  std::string url;             // rtsp://, http:// or https://
};

/// "file", "folder", "device" or "url".
std::string_view camera_source_kind_name(CameraSource::Kind kind);

struct SiteCamera {
  std::string name;
  CameraSource source;
  std::filesystem::path calibration_file;  // resolved against the site file's folder
  /// Rough optical centre in the field frame (e.g. "pole at the north-east corner, 5 m high");
  /// tells apart poses that the reference layout alone cannot (a symmetric court).
  std::optional<Vec3> position_hint_m;
};

/// A reference ball (table-tennis ball) at a point the user measured on the floor.
struct ReferenceBall {
  std::string name;
  Vec2 floor_position_m = Vec2::Zero();  // where it rests, field frame
};

/// An object's colour as the cameras see it in daylight, 8-bit R, G, B.
struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  cv::Vec3b bgr() const { return {b, g, r}; }
  static Rgb from_bgr(const cv::Vec3b& bgr) { return {bgr[2], bgr[1], bgr[0]}; }
};

struct SiteColours {
  Rgb ball{225, 250, 45};            // fluorescent yellow tennis ball
  Rgb reference_ball{255, 100, 20};  // orange table-tennis ball
  Rgb robot_front{255, 80, 180};     // pink marker
  Rgb robot_back{30, 80, 220};       // blue marker
};

struct SiteRobot {
  double marker_radius_m = 0.045;
  double marker_height_m = 0.345;   // marker centres above the floor
  double collector_width_m = 0.70;  // the report's collector (section 7.8)
  double collector_x_m = 0.30;      // collector mouth ahead of the robot's reference point
  double max_speed_mps = 1.0;       // driving speed of a small differential-drive collector
  double turn_rate_dps = 90.0;      // turning on the spot
  double max_accel_mps2 = 1.0;      // speeding up and braking
  double turn_accel_dps2 = 360.0;   // turn rate's change
  /// The basket: balls it holds (a 60-ball hopper: scenes of up to 60 balls never unload), where
  /// it is emptied (the collector's mouth there; absent: Site::unload_point()'s default) and how
  /// long emptying takes, the robot standing.
  int capacity = 60;
  std::optional<Vec2> unload_m;
  double unload_s = 5.0;
};

struct Site {
  std::filesystem::path file;  // the site file itself
  SiteCourt court;
  double ball_radius_m = 0.0335;
  double reference_ball_radius_m = 0.02;
  std::vector<ReferenceBall> reference_balls;  // in file order
  SiteColours colours;
  SiteRobot robot;
  std::vector<SiteCamera> cameras;

  /// A reference ball's centre in the field frame (it rests on the floor: z = radius).
  Vec3 reference_center_in_field(const ReferenceBall& ball) const;
  /// Where the basket is emptied: robot.unload_m, else 1.5 m inside the east fence on the
  /// court's long axis (behind the baseline, clear of the fence's lane).
  Vec2 unload_point() const;
};

/// Parses a site file's text; `file` names it in messages and its folder resolves relative paths.
/// Throws InputError "<file>:<line>: key '<key>' <what was expected>" for a wrong type or value,
/// a missing key or an unknown one.
Site parse_site(std::string_view text, const std::filesystem::path& file);

/// Reads and parses a site file.
Site read_site(const std::filesystem::path& file);

/// `site` as a site file's text that parse_site reads back to the same values (numbers in their
/// shortest exact form): what a recording keeps to replay the run (docs/recording.md). Paths are
/// written as they are; a camera without a calibration file gets `NAME.yml`, one without a
/// source file `NAME.png`, so that the text parses.
std::string site_file_text(const Site& site);

}  // namespace ballsight
