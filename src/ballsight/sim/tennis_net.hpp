#pragma once
// The tennis net as the court renderer sees it (spec: NetSpec in tennis_court.hpp): a vertical
// plane on the net line x = 0 between the post centres, from the floor up to the top cord, and two
// round posts. The centre strap holds the cord down, so the top cord is modelled as two straight
// lines from each post top down to the centre (the sag between them, a centimetre or two, is
// left out); the white band is the top band_depth_m of the plane. The plane has no thickness.

#include <array>
#include <opencv2/core.hpp>
#include <optional>

#include "ballsight/core/geometry.hpp"
#include "ballsight/core/raycast_box.hpp"
#include "ballsight/sim/tennis_court.hpp"

namespace ballsight::sim {

enum class NetPart { mesh, band, post };

struct NetHit {
  double t = 0.0;
  Vec3 normal_in_field = Vec3::Zero();  // of the surface hit, facing the ray's origin
  NetPart part = NetPart::mesh;
};

class TennisNet {
 public:
  /// The net of `court`, or nullopt when court.net.enabled is false.
  static std::optional<TennisNet> of(const TennisCourtSpec& court);

  const NetSpec& spec() const { return spec_; }
  /// Feet of the post centres on the floor: (0, -post_y_m) and (0, +post_y_m).
  std::array<Vec2, 2> post_positions() const;
  /// Height of the top cord at `y_m` across the court, |y_m| <= post_y_m.
  double top_height_m(double y_m) const;
  /// The box around the net and its posts: its footprint is what a ball or the robot must keep
  /// clear of, its image bounds where the renderer looks for the net.
  FloorBox bounds() const;
  /// First hit of the ray `origin + t * direction` (field frame) with the net or a post.
  std::optional<NetHit> intersect(const Vec3& origin, const Vec3& direction) const;
  const cv::Vec3b& albedo(NetPart part) const;

 private:
  TennisNet(const NetSpec& spec, double post_y_m) : spec_(spec), post_y_m_(post_y_m) {}

  NetSpec spec_;
  double post_y_m_ = 0.0;
};

}  // namespace ballsight::sim
