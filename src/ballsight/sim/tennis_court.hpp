#pragma once
// A tennis court as the floor of the court simulator: the ITF line layout on a hard court, a
// differently coloured run-off area around it and neutral ground beyond, and the net across it
// (geometry and ray test in tennis_net.hpp).
//
// Field frame: origin at the court centre (where the net line crosses the centre line), x along
// the length, y across, z up, metres. Court dimensions are to the outer edges of the lines (ITF
// Rules of Tennis, Appendix: "The Court").

#include <opencv2/core.hpp>
#include <optional>
#include <string_view>
#include <vector>

#include "ballsight/core/geometry.hpp"
#include "ballsight/sim/colours.hpp"

namespace ballsight::sim {

/// An axis-aligned rectangle on the ground, metres.
struct GroundRect {
  double x_min = 0.0, x_max = 0.0, y_min = 0.0, y_max = 0.0;

  bool contains(const Vec2& p) const {
    return p.x() >= x_min && p.x() <= x_max && p.y() >= y_min && p.y() <= y_max;
  }
};

/// The net on the net line x = 0, between two round posts outside the doubles sidelines: 1.07 m
/// high at the posts, 0.914 m at the centre strap, a white band 5-6.35 cm deep along the top cord,
/// round posts at most 15 cm across. Its mesh is dense and dark: the simulator renders it opaque.
// ITF Rules of Tennis, rule 1 "The Court": the net, the posts and the band.
struct NetSpec {
  bool enabled = true;                    // false: a court without a net (the simulator of before)
  double post_outside_doubles_m = 0.914;  // post centre from the doubles sideline's outer edge
  double post_height_m = 1.07;            // the posts, and the top cord where it meets them
  double centre_height_m = 0.914;         // the top cord at the centre strap
  double post_radius_m = 0.04;
  double band_depth_m = 0.06;  // white band along the top cord

  cv::Vec3b mesh_bgr{40, 45, 40};     // dark net (BGR albedo)
  cv::Vec3b band_bgr{238, 240, 240};  // white band
  cv::Vec3b post_bgr{45, 70, 40};     // dark green posts
};

struct TennisCourtSpec {
  double length_m = 23.77;                // baseline to baseline
  double doubles_width_m = 10.97;         // between the doubles sidelines
  double singles_width_m = 8.23;          // between the singles sidelines
  double service_line_from_net_m = 6.40;  // net line to the outer edge of a service line
  double line_width_m = 0.05;
  double centre_mark_length_m = 0.10;
  double surround_length_m = 36.0;  // run-off area, centred on the court
  double surround_width_m = 18.0;

  cv::Vec3b court_bgr{88, 128, 70};     // green hard court (BGR albedo)
  cv::Vec3b surround_bgr{80, 92, 52};   // darker teal-green run-off
  cv::Vec3b ground_bgr{128, 134, 138};  // neutral ground beyond the run-off
  cv::Vec3b line_bgr{238, 240, 240};    // white lines
  // The reference balls the cameras are posed from: orange table-tennis balls (the report's),
  // violet ones where orange does not stand out (set_court_surface).
  cv::Vec3b reference_ball_bgr{20, 100, 255};
  // The colours of the robot's marker balls on this site (make_court_scene paints them): pink at
  // the front, blue at the back, violet at the back on a blue court (set_court_surface).
  cv::Vec3b robot_front_marker_bgr = kPinkMarkerBgr;
  cv::Vec3b robot_back_marker_bgr = kBlueMarkerBgr;
  NetSpec net;

  /// Throws InputError naming the first invalid field.
  void validate() const;

  /// The doubles court (outer edges of baselines and doubles sidelines).
  GroundRect court_rect() const;
  GroundRect surround_rect() const;
  /// The painted lines: baselines, doubles and singles sidelines, service lines, centre service
  /// line and centre marks.
  std::vector<GroundRect> line_rects() const;
};

/// The surfaces the simulator paints a court with: a green or blue acrylic hard court (green
/// run-off), a red one (red acrylic, the colour of clay), bare concrete, and an indoor hall's
/// wooden floor (a darker wood around it).
enum class CourtSurface { green, blue, red, concrete, wood };

/// "green", "blue", "red", "concrete", "wood".
std::string_view court_surface_name(CourtSurface surface);
/// The surface of that name, or nullopt.
std::optional<CourtSurface> court_surface_named(std::string_view name);
/// Paints the court and its run-off with `surface` (albedo; the lines stay white) and sets the
/// colours the site chooses for it: `reference_ball_bgr` and `robot_back_marker_bgr` are reset
/// on every call (set colours of one's own after it). Green is the simulator's default court.
/// On a red or wooden court the reference balls are violet (kVioletBgr): orange lies within
/// those floors' hues; violet (272 degrees of hue) stands about 50 degrees from both robot
/// markers (pink 326, blue 224) and 110 from the red court's teal run-off (162). On a blue court
/// (hue 209) the robot's back marker is violet: a blue one (224) is lost in the court's blob.
void set_court_surface(TennisCourtSpec& court, CourtSurface surface);

/// Albedo of the floor at `p_in_field`, box-filtered over a footprint of half-sizes
/// `half_footprint_m` (x, y) so that lines and edges are anti-aliased. Zero footprint samples.
cv::Vec3f floor_albedo(const TennisCourtSpec& court, const std::vector<GroundRect>& lines,
                       const Vec2& p_in_field, const Vec2& half_footprint_m);

}  // namespace ballsight::sim
