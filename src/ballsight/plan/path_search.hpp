#pragma once
// Improvement search for an open path through every node of a travel model (travel_model.hpp):
// 2-opt and Or-opt moves (segments of 1-3 nodes, either way round) over neighbour lists with
// don't-look bits, first improvement; then iterated local search (Lourenco, Martin & Stuetzle,
// "Iterated Local Search", 2003): a local double-bridge kick, local search from the kicked
// nodes, walked on when not much worse (threshold accepting), the best path kept. Moves are priced
// with the model's turn costs, which change only at the ends of a reversed stretch because turns
// are symmetric.
//
// Header-only: instantiated for TravelModel (routes on the court) and MatrixModel (TSPLIB).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <initializer_list>
#include <numeric>
#include <random>
#include <vector>

#include "ballsight/plan/travel_model.hpp"

namespace ballsight {

struct PathSearchOptions {
  bool fixed_end = false;  // the last node stays: a point to return to
  int neighbours = 16;     // candidate list length per node (10 loses 1-2 % on clusters)
  int kick_span = 30;      // longest stretch a kick moves
  /// A kicked path that is at most this much worse (relative) is walked on, the best one kept:
  /// threshold accepting (Dueck & Scheuer, J. Comput. Phys. 90, 1990). 0.3 % took gr120 from
  /// 7029 to 6951 (optimum 6942) at the default effort; 0 gets stuck.
  double accept_worse = 0.003;
  std::uint64_t seed = 1;
};

/// One call of the search: what stays, where to look first, how long to go on.
struct Improvement {
  int fixed_prefix = 1;    // path[0 .. fixed_prefix - 1] stay: the start, and a kept target
  std::vector<int> dirty;  // nodes to look at first; all when empty
  int kicks = 0;           // iterated local search: kicks tried after the first local optimum
};

/// Cost of driving `path` (legs and turns, from the start's heading).
template <class Model>
double path_cost(const Model& model, const std::vector<int>& path) {
  double total = 0.0;
  for (std::size_t i = 0; i < path.size(); ++i) {
    const int prev = i == 0 ? kHeading : path[i - 1];
    const int next = i + 1 < path.size() ? path[i + 1] : kNone;
    total += model.turn(prev, path[i], next);
    if (next != kNone) total += model.leg(path[i], next);
  }
  return total;
}

/// Greedy start: node 0, then always the cheapest next of nodes 1 .. count - 1 (turn included).
template <class Model>
std::vector<int> nearest_neighbour_path(const Model& model, int count) {
  std::vector<int> path{0};
  std::vector<int> left;
  for (int i = 1; i < count; ++i) left.push_back(i);
  while (!left.empty()) {
    const int prev = path.size() > 1 ? path[path.size() - 2] : kHeading;
    const int at = path.back();
    const auto cost = [&](int next) { return model.turn(prev, at, next) + model.leg(at, next); };
    const auto best =
        std::min_element(left.begin(), left.end(), [&](int a, int b) { return cost(a) < cost(b); });
    path.push_back(*best);
    left.erase(best);
  }
  return path;
}

/// The search over one model; keeps its neighbour lists for repeated use (re-planning).
template <class Model>
class PathSearch {
 public:
  PathSearch(const Model& model, PathSearchOptions options)
      : model_(model), options_(options), rng_(options.seed) {
    const int n = model_.size();
    const auto k = static_cast<std::size_t>(std::max(0, std::min(options_.neighbours, n - 1)));
    neighbours_.assign(static_cast<std::size_t>(n), {});
    std::vector<std::pair<double, int>> row;
    for (int a = 0; a < n; ++a) {
      row.clear();
      for (int b = 0; b < n; ++b) {
        if (b != a) row.emplace_back(model_.leg(a, b), b);
      }
      std::partial_sort(row.begin(), row.begin() + static_cast<std::ptrdiff_t>(k), row.end());
      auto& list = neighbours_[static_cast<std::size_t>(a)];
      for (std::size_t t = 0; t < k; ++t) list.push_back(row[t].second);
    }
  }

  /// Improves `path` (node 0 first) in place; returns its cost after the search.
  double improve(std::vector<int>& path, const Improvement& how) {
    fixed_prefix_ = how.fixed_prefix;
    bind(path);
    if (how.dirty.empty()) {
      for (int i = lo(); i <= hi(); ++i) activate(path[static_cast<std::size_t>(i)]);
    } else {
      for (const int node : how.dirty) activate(node);
    }
    local_search(path);
    double best_cost = path_cost(model_, path);
    double current_cost = best_cost;
    std::vector<int> best = path, current = path;
    for (int kick = 0; kick < how.kicks && hi() - lo() >= 3; ++kick) {
      double cost = current_cost + double_bridge(path);
      cost += local_search(path);
      if (cost < best_cost - 1e-12) {
        best_cost = cost;
        best = path;
      }
      if (cost <= current_cost * (1.0 + options_.accept_worse) + 1e-12) {
        current_cost = cost;
        current = path;
      } else {
        path = current;
        bind(path);
      }
    }
    path = best;
    return best_cost;
  }

 private:
  using Path = std::vector<int>;
  /// A short run of nodes (sentinels allowed at its ends) on the stack: moves are priced in the
  /// hot loop, where a heap allocation would cost more than the pricing.
  struct Window {
    static constexpr int kCapacity = 16;  // a near Or-opt move: 3 + 2 + 3 nodes and context
    std::array<int, kCapacity> v;
    int n = 0;
    Window() = default;
    Window(std::initializer_list<int> nodes) {
      for (const int x : nodes) push(x);
    }
    void push(int x) { v[static_cast<std::size_t>(n++)] = x; }
    void append(const Window& w) {
      for (int t = 0; t < w.n; ++t) push(w.v[static_cast<std::size_t>(t)]);
    }
    int operator[](int t) const { return v[static_cast<std::size_t>(t)]; }
  };

  int at(int i) const {
    if (i < 0) return kHeading;
    if (i >= m_) return kNone;
    return (*path_)[static_cast<std::size_t>(i)];
  }
  int lo() const { return fixed_prefix_; }
  int hi() const { return m_ - 1 - (options_.fixed_end ? 1 : 0); }

  void bind(Path& path) {
    path_ = &path;
    m_ = static_cast<int>(path.size());
    pos_.assign(static_cast<std::size_t>(model_.size()), -1);
    for (int i = 0; i < m_; ++i)
      pos_[static_cast<std::size_t>(path[static_cast<std::size_t>(i)])] = i;
    active_.assign(static_cast<std::size_t>(model_.size()), false);
    queue_.clear();
  }
  void activate(int node) {
    if (node < 0 || active_[static_cast<std::size_t>(node)]) return;
    active_[static_cast<std::size_t>(node)] = true;
    queue_.push_back(node);
  }
  int pos(int node) const { return pos_[static_cast<std::size_t>(node)]; }

  /// Turns at the inner nodes of `w` (its first and last are context) and legs between them.
  double window(const Window& w) const {
    double total = 0.0;
    for (int t = 1; t + 1 < w.n; ++t) {
      if (w[t] < 0) continue;
      total += model_.turn(w[t - 1], w[t], w[t + 1]);
      if (t + 2 < w.n && w[t + 1] >= 0) total += model_.leg(w[t], w[t + 1]);
    }
    return total;
  }
  /// window() of path[first .. last] read in place (first and last are context).
  double range_cost(int first, int last) const {
    double total = 0.0;
    for (int i = first + 1; i < last; ++i) {
      const int node = at(i);
      if (node < 0) continue;
      total += model_.turn(at(i - 1), node, at(i + 1));
      if (i + 1 < last && at(i + 1) >= 0) total += model_.leg(node, at(i + 1));
    }
    return total;
  }
  /// path[first .. last] (sentinels outside).
  Window slice(int first, int last) const {
    Window w;
    for (int i = first; i <= last; ++i) w.push(at(i));
    return w;
  }

  void reindex(int first, int last) {
    for (int i = first; i <= last; ++i) pos_[static_cast<std::size_t>(at(i))] = i;
  }
  void touch(int first, int last) {
    for (int i = std::max(first, 0); i <= std::min(last, m_ - 1); ++i) activate(at(i));
  }

  /// Cost change of reversing path[i .. j].
  double reversal_delta(int i, int j) const {
    const double before = window({at(i - 2), at(i - 1), at(i), at(i + 1)}) +
                          window({at(j - 1), at(j), at(j + 1), at(j + 2)});
    const double after = window({at(i - 2), at(i - 1), at(j), at(j - 1)}) +
                         window({at(i + 1), at(i), at(j + 1), at(j + 2)});
    return after - before;
  }
  void reverse(int i, int j) {
    std::reverse(path_->begin() + i, path_->begin() + j + 1);
    reindex(i, j);
    touch(i - 1, i);
    touch(j, j + 1);
  }

  /// Cost change of taking path[s .. e] out and joining its neighbours (for far moves).
  double removal_delta(int s, int e) const {
    return window({at(s - 2), at(s - 1), at(e + 1), at(e + 2)}) - window(slice(s - 2, e + 2));
  }
  /// Cost change of moving path[s .. e] to sit between positions k and k + 1 (k < s - 1 or
  /// k > e), reversed when asked; `removal` is removal_delta(s, e). Far moves price the removal
  /// and the insertion apart, near ones one slice.
  double move_delta(int s, int e, int k, bool reversed, double removal) const {
    Window seg = slice(s, e);
    if (reversed) std::reverse(seg.v.begin(), seg.v.begin() + seg.n);
    if (k >= e + 2 || k <= s - 3) {
      Window inserted{at(k - 1), at(k)};
      inserted.append(seg);
      inserted.append({at(k + 1), at(k + 2)});
      return removal + window(inserted) - window(slice(k - 1, k + 2));
    }
    const int first = std::min(s, k + 1) - 2, last = std::max(e, k) + 2;
    Window after;
    for (int i = first; i <= last; ++i) {
      if (i >= s && i <= e) continue;
      if (i == k + 1 && k < s) after.append(seg);
      after.push(at(i));
      if (i == k && k > e) after.append(seg);
    }
    return window(after) - window(slice(first, last));
  }
  void move(int s, int e, int k, bool reversed) {
    auto begin = path_->begin();
    if (reversed) std::reverse(begin + s, begin + e + 1);
    const int len = e - s + 1;
    if (k > e) {
      std::rotate(begin + s, begin + e + 1, begin + k + 1);
      reindex(s, k);
      touch(s - 1, s);
      touch(k - len, k - len + 1);
      touch(k, k + 1);
    } else {
      std::rotate(begin + k + 1, begin + s, begin + e + 1);
      reindex(k + 1, e);
      touch(k, k + 1);
      touch(k + len, k + len + 1);
      touch(e, e + 1);
    }
  }

  /// Tries the moves that join `a` to a neighbour; applies the first that saves. Returns the
  /// saving (negative) or 0.
  double try_node(int a) {
    constexpr double kGain = -1e-9;
    // Neighbour lists with the gain criterion: a move that joins a to c removes a leg at a, and
    // is looked for only while the new leg is shorter than the removed one.
    const int i = pos(a);
    const double before_a = at(i - 1) >= 0 ? model_.leg(at(i - 1), a) : 0.0;
    const double after_a = at(i + 1) >= 0 ? model_.leg(a, at(i + 1)) : 0.0;
    const double longest = std::max(before_a, after_a);
    // Or-opt's segments with a at one end: (start, end, leg cut at a); what taking each out
    // saves is priced when first needed.
    struct Segment {
      int s, e;
      double cut;
      double saved = 1.0;  // > 0: not priced yet or no saving
      bool priced = false;
    };
    std::array<Segment, 5> segments{{{i, i, longest},
                                     {i, i + 1, before_a},
                                     {i - 1, i, after_a},
                                     {i, i + 2, before_a},
                                     {i - 2, i, after_a}}};
    if (!options_.fixed_end) {
      // An open path's end is a neighbour of every node, joined for free: a becomes the last
      // node, by turning the rest of the path round or moving a's segment there. The gain
      // criterion from the other side: the new leg at the old last node must be shorter than
      // the leg cut.
      const int last = at(hi());
      if (i < hi() && at(i - 1) >= 0 && model_.leg(at(i - 1), last) < before_a) {
        const double d = reversal_delta(i, hi());
        if (d < kGain) {
          reverse(i, hi());
          return d;
        }
      }
      for (Segment& seg : segments) {
        if (seg.s < lo() || seg.e >= hi()) continue;
        const int other_end = seg.s == i ? at(seg.e) : at(seg.s);
        if (model_.leg(last, other_end) >= seg.cut) continue;
        if (!seg.priced) {
          seg.saved = removal_delta(seg.s, seg.e);
          seg.priced = true;
        }
        if (seg.saved >= 0.0) continue;
        const double d = move_delta(seg.s, seg.e, hi(), seg.s == i && seg.e != i, seg.saved);
        if (d < kGain) {
          move(seg.s, seg.e, hi(), seg.s == i && seg.e != i);
          return d;
        }
      }
    }
    for (const int c : neighbours_[static_cast<std::size_t>(a)]) {
      const double joined = model_.leg(a, c);
      if (joined >= longest) break;
      const int j = pos(c);
      if (j < 0) continue;
      // 2-opt: the two reversals that make a and c adjacent.
      const int x = std::min(i, j), y = std::max(i, j);
      for (const auto& [first, last] : {std::pair{x + 1, y}, std::pair{x, y - 1}}) {
        if (first < lo() || last > hi() || last - first < 1) continue;
        const double d = reversal_delta(first, last);
        if (d < kGain) {
          reverse(first, last);
          return d;
        }
      }
      // Or-opt: a segment moved so that its end a sits next to c (before or after it).
      for (Segment& seg : segments) {
        if (seg.s < lo() || seg.e > hi() || joined >= seg.cut) continue;
        if (!seg.priced) {
          seg.saved = removal_delta(seg.s, seg.e);
          seg.priced = true;
        }
        if (seg.saved >= 0.0) continue;
        for (const int k : {j - 1, j}) {
          if (k < lo() - 1 || k > hi() || (k >= seg.s - 1 && k <= seg.e)) continue;
          // After c (k = j) a leads the segment, before it (k = j - 1) a closes it.
          const bool reversed = (k == j) == (seg.e == i && seg.s != i);
          const double d = move_delta(seg.s, seg.e, k, reversed, seg.saved);
          if (d < kGain) {
            move(seg.s, seg.e, k, reversed);
            return d;
          }
        }
      }
    }
    return 0.0;
  }

  double local_search(Path& path) {
    path_ = &path;
    double total = 0.0;
    while (!queue_.empty()) {
      const int a = queue_.front();
      queue_.pop_front();
      active_[static_cast<std::size_t>(a)] = false;
      if (pos(a) < lo() || pos(a) > hi()) continue;
      const double d = try_node(a);
      if (d < 0.0) {
        total += d;
        activate(a);
      }
    }
    return total;
  }

  /// Swaps two short neighbouring stretches (a local double bridge); returns the cost change.
  double double_bridge(Path& path) {
    const int span = hi() - lo() + 1;
    const int max_len = std::max(1, std::min(options_.kick_span, span / 3));
    const auto draw = [&](int n) {
      return static_cast<int>(rng_() % static_cast<std::uint64_t>(n));
    };
    const int len_b = 1 + draw(max_len), len_c = 1 + draw(max_len);
    const int i = lo() + draw(std::max(1, span - len_b - len_c + 1));
    const int last = i + len_b + len_c - 1;
    const double before = range_cost(i - 2, last + 2);
    std::rotate(path.begin() + i, path.begin() + i + len_b, path.begin() + last + 1);
    reindex(i, last);
    const double after = range_cost(i - 2, last + 2);
    touch(i - 1, i);
    touch(last - len_b, last - len_b + 1);
    touch(last, last + 1);
    return after - before;
  }

  const Model& model_;
  PathSearchOptions options_;
  std::mt19937_64 rng_;
  std::vector<std::vector<int>> neighbours_;
  int fixed_prefix_ = 1;
  Path* path_ = nullptr;
  int m_ = 0;
  std::vector<int> pos_;
  std::vector<bool> active_;
  std::deque<int> queue_;
};

}  // namespace ballsight
