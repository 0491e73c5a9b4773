#include "ballsight/world/collection_sites.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ballsight/core/error.hpp"

namespace ballsight {

std::vector<CollectionSite> collection_sites(const std::vector<Vec2>& balls,
                                             double collector_width_m) {
  require(std::isfinite(collector_width_m) && collector_width_m > 0.0,
          "collection sites collector_width_m", "must be positive");
  const size_t n = balls.size();
  std::vector<std::vector<int>> groups(n);
  for (size_t i = 0; i < n; ++i) groups[i] = {static_cast<int>(i)};
  // Complete linkage: the width of a union is the largest pairwise ball distance across it.
  std::vector<std::vector<double>> width(n, std::vector<double>(n, 0.0));
  for (size_t i = 0; i < n; ++i)
    for (size_t j = 0; j < n; ++j) width[i][j] = (balls[i] - balls[j]).norm();
  std::vector<bool> alive(n, true);
  while (true) {
    double best = std::numeric_limits<double>::max();
    size_t best_i = 0, best_j = 0;
    for (size_t i = 0; i < n; ++i) {
      if (!alive[i]) continue;
      for (size_t j = i + 1; j < n; ++j) {
        if (alive[j] && width[i][j] < best) best = width[i][j], best_i = i, best_j = j;
      }
    }
    if (best > collector_width_m) break;
    groups[best_i].insert(groups[best_i].end(), groups[best_j].begin(), groups[best_j].end());
    alive[best_j] = false;
    for (size_t k = 0; k < n; ++k) {
      width[best_i][k] = width[k][best_i] = std::max(width[best_i][k], width[best_j][k]);
    }
    width[best_i][best_i] = 0.0;
  }
  std::vector<CollectionSite> sites;
  for (size_t i = 0; i < n; ++i) {
    if (!alive[i]) continue;
    CollectionSite site;
    site.balls = groups[i];
    std::sort(site.balls.begin(), site.balls.end());
    for (int b : site.balls) site.center_m += balls[static_cast<size_t>(b)];
    site.center_m /= static_cast<double>(site.balls.size());
    for (int a : site.balls)
      for (int b : site.balls)
        site.diameter_m =
            std::max(site.diameter_m,
                     (balls[static_cast<size_t>(a)] - balls[static_cast<size_t>(b)]).norm());
    sites.push_back(std::move(site));
  }
  std::sort(sites.begin(), sites.end(), [](const CollectionSite& a, const CollectionSite& b) {
    return a.balls.front() < b.balls.front();
  });
  return sites;
}

}  // namespace ballsight
