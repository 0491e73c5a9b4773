#pragma once
// What stands on the simulated tennis court: tennis balls, reference balls (table-tennis balls at
// known positions, for the cameras' extrinsics), the robot (a box marked by a pink ball at the
// front and a blue ball at the back, as in the tennis-ball-collecting-robot report, section 7.6)
// , the lighting and distractors of a ball's colour (fallen leaves, a water bottle). The court and
// the cameras are the installation (court_rig.hpp).

#include <opencv2/core.hpp>
#include <optional>
#include <string_view>
#include <vector>

#include "ballsight/core/geometry.hpp"
#include "ballsight/core/raycast_box.hpp"
#include "ballsight/sim/colours.hpp"
#include "ballsight/sim/image_effects.hpp"

namespace ballsight::sim {

enum class ObjectKind { tennis_ball, reference_ball, robot_front_marker, robot_back_marker };

/// "tennis_ball", "reference_ball", "robot_front_marker", "robot_back_marker".
std::string_view object_kind_name(ObjectKind kind);

inline constexpr double kTennisBallRadiusM = 0.0335;
inline constexpr double kReferenceBallRadiusM = 0.02;

/// A sphere in the scene; `id` numbers the objects of one kind from 0.
struct SceneSphere {
  ObjectKind kind = ObjectKind::tennis_ball;
  int id = 0;
  Vec3 center_in_field = Vec3::Zero();
  double radius_m = kTennisBallRadiusM;
  cv::Vec3b bgr = kTennisBallBgr;
};

/// The robot as a box standing on the floor, centred on its pose, with two marker balls on top
/// on its centre line: by default the pink one at the front (+x of the robot), the blue one at
/// the back.
struct RobotBox {
  Pose2D pose;  // field_from_robot: position of the box centre and heading of its front
  double length_m = 0.60;
  double width_m = 0.45;
  double height_m = 0.30;
  double marker_radius_m = 0.045;
  double marker_inset_m = 0.10;  // marker centre from the front/back face
  cv::Vec3b bgr{128, 128, 128};
  cv::Vec3b front_marker_bgr = kPinkMarkerBgr;
  cv::Vec3b back_marker_bgr = kBlueMarkerBgr;

  /// Throws InputError naming the first invalid field.
  void validate() const;
  SceneSphere front_marker() const;
  SceneSphere back_marker() const;
};

/// A band of shadow across the ground (the shade of a building or a row of trees): inside it the
/// sun is blocked and only the ambient light remains, for the floor and objects alike.
struct ShadowBand {
  Vec2 point_in_field = Vec2::Zero();  // a point on the band's centre line
  Vec2 direction = Vec2::UnitX();      // unit vector along the centre line
  double width_m = 3.0;
  double soft_edge_m = 0.3;  // width of the penumbra on each side
};

/// The light of a scene: sun with a soft-edged shadow band (the shade of trees), low sun with
/// a hard-edged one and little sky light (the shade of a building), overcast (light from the
/// whole sky: top-lit, no shadow, darker), or indoor (a hall's ceiling lamps: top-lit, no
/// shadow, darker still, and warm: the camera's white balance leaves a yellow-red cast).
enum class LightCondition { sun, hard_shadow, overcast, indoor };

/// "sun", "hard_shadow", "overcast", "indoor".
std::string_view light_condition_name(LightCondition condition);
/// The condition of that name, or nullopt.
std::optional<LightCondition> light_condition_named(std::string_view name);

struct Lighting {
  LightCondition condition = LightCondition::sun;   // what the values below were drawn for
  Vec3 to_sun = Vec3(0.3, 0.2, 0.93).normalized();  // unit vector towards the sun, z > 0
  double ambient = 0.45;                            // share of light that is not direct sun
  std::optional<ShadowBand> shadow;

  /// Throws InputError naming the first invalid field.
  void validate() const;
  /// How much of the sun reaches ground position `p_in_field`: 1 in the open, 0 in the shadow.
  double sun_visibility(const Vec2& p_in_field) const;
  /// Light factor for a surface with unit `normal` at `p_in_field` (1 = full sun, head on).
  double irradiance(const Vec3& normal, const Vec3& p_in_field) const;
};

/// A fallen leaf flat on the floor: an ellipse of its own colour (a yellow-green one looks like a
/// ball's colour, not a ball's shape).
struct FloorLeaf {
  Vec2 center_in_field = Vec2::Zero();
  Vec2 axis = Vec2::UnitX();  // unit vector along its length
  double half_length_m = 0.06;
  double half_width_m = 0.03;
  cv::Vec3b bgr{60, 200, 170};

  bool covers(const Vec2& p_in_field) const;
};

/// A plastic water bottle standing upright on the floor: a cylinder of one colour (a sports
/// drink's yellow-green is a ball's colour, not a ball's shape).
struct FloorBottle {
  Vec2 center_in_field = Vec2::Zero();
  double radius_m = 0.035;
  double height_m = 0.23;
  cv::Vec3b bgr{40, 215, 175};

  /// First hit of the ray `origin + t * direction` (unit direction) with the bottle's side or
  /// top, from outside; nullopt when it misses.
  std::optional<BoxHit> intersect(const Vec3& origin, const Vec3& direction) const;
  /// The box that holds it (for the pixel box of its image).
  FloorBox bounds() const;
};

/// Something standing on the court that the robot must go round and the cameras see: a person
/// (an upright cylinder: legs, body and arms as one) or a bag (a box on the floor). A walking
/// person goes at `walk_mps` towards `walk_to` and back to where it began, again and again, and
/// stops while the robot is near (sim/court_world.hpp).
enum class ObstacleKind { person, bag };

/// "person", "bag".
std::string_view obstacle_kind_name(ObstacleKind kind);

struct CourtObstacle {
  ObstacleKind kind = ObstacleKind::person;
  Pose2D pose;                        // the footprint's centre; a bag's heading
  Vec2 half_size = Vec2(0.22, 0.22);  // a person: x is the radius; a bag: half length, width
  double height_m = 1.75;
  cv::Vec3b bgr{40, 40, 150};   // clothes or the bag's cloth
  std::optional<Vec2> walk_to;  // a walking person's turning point
  double walk_mps = 0.3;

  /// First hit of the ray `origin + t * direction` (unit direction) from outside; nullopt when
  /// it misses.
  std::optional<BoxHit> intersect(const Vec3& origin, const Vec3& direction) const;
  /// The box that holds it (for the pixel box of its image).
  FloorBox bounds() const;
  /// The distance on the floor from `p` to its footprint, 0 inside.
  double floor_distance(const Vec2& p) const;
};

struct CourtScene {
  std::vector<SceneSphere> balls;    // tennis balls and reference balls
  std::vector<FloorLeaf> leaves;     // distractors flat on the floor
  std::vector<FloorBottle> bottles;  // distractors standing on it
  std::vector<CourtObstacle> obstacles;
  RobotBox robot;
  Lighting lighting;
  ImageEffects effects;  // brightness gain (exposure), blur and sensor noise

  /// Throws InputError naming the first invalid field (e.g. "balls[3].radius_m: ...").
  void validate() const;
  /// Every sphere: the balls, then the robot's front and back markers.
  std::vector<SceneSphere> spheres() const;
};

}  // namespace ballsight::sim
