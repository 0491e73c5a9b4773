#include "ballsight/world/net_panel.hpp"

#include <cmath>

#include "ballsight/core/error.hpp"

namespace ballsight {

void NetPanel::validate() const {
  require(half_length_m > 0.0, "net half_length_m", "must be positive");
  require(height_posts_m > 0.0 && height_centre_m > 0.0, "net heights", "must be positive");
}

double NetPanel::top_m(double y_m) const {
  return height_centre_m + (height_posts_m - height_centre_m) * std::abs(y_m) / half_length_m;
}

bool NetPanel::hides(const Vec3& eye, const Vec3& point) const {
  if ((eye.x() > 0.0) == (point.x() > 0.0) || eye.x() == point.x()) return false;
  const double s = eye.x() / (eye.x() - point.x());  // where the sight line meets x = 0
  const Vec3 crossing = eye + s * (point - eye);
  return std::abs(crossing.y()) <= half_length_m && crossing.z() >= 0.0 &&
         crossing.z() <= top_m(crossing.y());
}

}  // namespace ballsight
