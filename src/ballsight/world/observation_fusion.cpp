#include "ballsight/world/observation_fusion.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <queue>

#include "ballsight/core/error.hpp"

namespace ballsight {

void FusionOptions::validate() const {
  require(std::isfinite(gate_chi2) && gate_chi2 > 0.0, "fusion gate_chi2", "must be positive");
  require(std::isfinite(search_radius_m) && search_radius_m > 0.0, "fusion search_radius_m",
          "must be positive");
}

namespace {

// A group of observations in information form.
struct Group {
  Eigen::Matrix2d information = Eigen::Matrix2d::Zero();
  Vec2 information_vector = Vec2::Zero();
  Vec2 position = Vec2::Zero();
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Identity();
  std::uint64_t cameras = 0;  // bit set
  std::vector<int> members;
  int version = 0;
  bool alive = true;

  void add(const Eigen::Matrix2d& info, const Vec2& info_vector, std::uint64_t camera_bits) {
    information += info;
    information_vector += info_vector;
    covariance = information.inverse();
    position = covariance * information_vector;
    cameras |= camera_bits;
  }
};

struct Candidate {
  double d2 = 0.0;
  int a = 0, b = 0;
  int version_a = 0, version_b = 0;
  bool operator>(const Candidate& other) const { return d2 > other.d2; }
};

}  // namespace

std::vector<FusedObject> fuse_observations(const std::vector<FieldObservation>& observations,
                                           const FusionOptions& options) {
  options.validate();
  std::vector<Group> groups(observations.size());
  for (size_t i = 0; i < observations.size(); ++i) {
    const FieldObservation& o = observations[i];
    require(o.camera >= 0 && o.camera < 64, "fusion", "camera index must be within [0, 64)");
    const Eigen::Matrix2d info = o.covariance_m2.inverse();
    groups[i].add(info, info * o.position_m, std::uint64_t{1} << o.camera);
    groups[i].members = {static_cast<int>(i)};
  }
  const double radius2 = options.search_radius_m * options.search_radius_m;
  std::priority_queue<Candidate, std::vector<Candidate>, std::greater<>> queue;
  const auto consider = [&](int a, int b) {
    const Group& ga = groups[static_cast<size_t>(a)];
    const Group& gb = groups[static_cast<size_t>(b)];
    if ((ga.cameras & gb.cameras) != 0) return;
    if ((ga.position - gb.position).squaredNorm() > radius2) return;
    const double d2 = mahalanobis_squared(ga.position, ga.covariance, gb.position, gb.covariance);
    if (d2 <= options.gate_chi2) queue.push({d2, a, b, ga.version, gb.version});
  };
  const int n = static_cast<int>(groups.size());
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) consider(a, b);

  while (!queue.empty()) {
    const Candidate c = queue.top();
    queue.pop();
    Group& ga = groups[static_cast<size_t>(c.a)];
    Group& gb = groups[static_cast<size_t>(c.b)];
    if (!ga.alive || !gb.alive || ga.version != c.version_a || gb.version != c.version_b) continue;
    ga.add(gb.information, gb.information_vector, gb.cameras);
    ga.members.insert(ga.members.end(), gb.members.begin(), gb.members.end());
    ++ga.version;
    gb.alive = false;
    for (int other = 0; other < n; ++other)
      if (other != c.a && groups[static_cast<size_t>(other)].alive) consider(c.a, other);
  }

  std::vector<FusedObject> out;
  for (const Group& g : groups) {
    if (!g.alive) continue;
    FusedObject object;
    object.position_m = g.position;
    object.covariance_m2 = g.covariance;
    object.observations = g.members;
    std::sort(object.observations.begin(), object.observations.end());
    for (int camera = 0; camera < 64; ++camera)
      if (g.cameras & (std::uint64_t{1} << camera)) object.cameras.push_back(camera);
    out.push_back(std::move(object));
  }
  return out;
}

}  // namespace ballsight
