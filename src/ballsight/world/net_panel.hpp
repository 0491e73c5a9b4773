#pragma once
// The tennis net as the court cameras see it: an opaque panel on the net line x = 0 between the
// posts, from the floor up to the top cord, which falls in a straight line from each post to the
// centre strap (ITF Rules of Tennis, rule 1: 1.07 m at the posts, 0.914 m at the centre). The
// world model asks it whether the net explains why a camera missed a ball.

#include "ballsight/core/geometry.hpp"

namespace ballsight {

struct NetPanel {
  double half_length_m = 10.97 / 2.0 + 0.914;  // centre line to a post
  double height_posts_m = 1.07;
  double height_centre_m = 0.914;

  /// Throws InputError naming the first invalid field.
  void validate() const;
  /// The top cord's height at `y_m` across the court (|y_m| <= half_length_m).
  double top_m(double y_m) const;
  /// The straight line of sight from `eye` to `point` passes through the panel.
  bool hides(const Vec3& eye, const Vec3& point) const;
};

}  // namespace ballsight
