#include "ballsight/plan/ball_groups.hpp"

#include <algorithm>

namespace ballsight {
namespace {

double farthest_from(const Vec2& centre, const std::vector<Vec2>& points,
                     const std::vector<int>& members) {
  double r = 0.0;
  for (const int m : members)
    r = std::max(r, (points[static_cast<std::size_t>(m)] - centre).norm());
  return r;
}

}  // namespace

std::vector<BallGroup> group_balls(const std::vector<Vec2>& points, const std::vector<int>& which,
                                   double max_radius_m) {
  std::vector<int> order = which;
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const Vec2 &p = points[static_cast<std::size_t>(a)], &q = points[static_cast<std::size_t>(b)];
    return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y());
  });
  std::vector<bool> taken(points.size(), false);
  std::vector<BallGroup> groups;
  std::vector<std::pair<double, int>> near;
  for (const int seed : order) {
    if (taken[static_cast<std::size_t>(seed)]) continue;
    const Vec2& s = points[static_cast<std::size_t>(seed)];
    BallGroup group{s, 0.0, {seed}};
    taken[static_cast<std::size_t>(seed)] = true;
    near.clear();
    for (const int other : order) {
      const double d = (points[static_cast<std::size_t>(other)] - s).norm();
      if (!taken[static_cast<std::size_t>(other)] && d <= 2.0 * max_radius_m) {
        near.emplace_back(d, other);
      }
    }
    std::sort(near.begin(), near.end());
    for (const auto& [d, other] : near) {
      std::vector<int> members = group.balls;
      members.push_back(other);
      Vec2 centre = Vec2::Zero();
      for (const int m : members) centre += points[static_cast<std::size_t>(m)];
      centre /= static_cast<double>(members.size());
      const double radius = farthest_from(centre, points, members);
      if (radius > max_radius_m) continue;
      group = {centre, radius, std::move(members)};
      taken[static_cast<std::size_t>(other)] = true;
    }
    groups.push_back(std::move(group));
  }
  return groups;
}

}  // namespace ballsight
