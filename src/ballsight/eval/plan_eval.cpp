#include "ballsight/eval/plan_eval.hpp"

#include <algorithm>
#include <cstdio>

#include "ballsight/camera/image_file.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/core/text_format.hpp"
#include "ballsight/eval/plot_inputs.hpp"
#include "ballsight/eval/wall_clock.hpp"
#include "ballsight/plan/exact_path.hpp"
#include "ballsight/plan/planner.hpp"
#include "ballsight/sim/tennis_court.hpp"
#include "ballsight/viz/route_plot.hpp"
#include "ballsight/world/collection_sites.hpp"

namespace ballsight::eval {
namespace {

constexpr PlannerKind kCompared[] = {PlannerKind::priority, PlannerKind::nearest,
                                     PlannerKind::ballsight};
const cv::Scalar kColours[] = {{40, 40, 220}, {200, 130, 30}, {30, 160, 30}};

double gap_pct(double value, double reference) {
  return 100.0 * (value / reference - 1.0);
}

/// What one planner did on one problem.
struct Outcome {
  std::string planner;
  double time_s = 0.0, length_m = 0.0, plan_ms = 0.0;
  std::optional<double> gap_to_optimal_pct, gap_to_long_run_pct;
};

void add(PlannerFigures& f, const Outcome& o) {
  f.time_s.add(o.time_s);
  f.length_m.add(o.length_m);
  f.plan_ms.add(o.plan_ms);
  if (o.gap_to_optimal_pct) f.gap_to_optimal_pct.add(*o.gap_to_optimal_pct);
  if (o.gap_to_long_run_pct) f.gap_to_long_run_pct.add(*o.gap_to_long_run_pct);
}

/// The compared planners' routes on one problem, labelled and coloured for a map.
std::vector<RouteLayer> compared_routes(const PlanningProblem& problem, std::uint64_t seed) {
  std::vector<RouteLayer> layers;
  for (const PlannerKind kind : kCompared) {
    PlannerOptions planner;
    planner.kind = kind;
    planner.seed = seed;
    Route route = plan(problem, planner);
    char label[96];
    std::snprintf(label, sizeof label, "%s: %.1f s, %.1f m", route.planner.c_str(), route.time_s,
                  route.length_m);
    layers.push_back({label, kColours[layers.size()], std::move(route)});
  }
  return layers;
}

/// One problem planned by every planner (and the references); pictured when `plot_name` is set.
std::vector<Outcome> evaluate(const PlanningProblem& problem, const PlanEvalOptions& options,
                              std::uint64_t seed, const std::string& plot_name) {
  const int n = static_cast<int>(problem.balls.size());
  std::optional<double> optimum;
  if (n <= kMaxExactNodes) {
    PlannerOptions exact;
    exact.kind = PlannerKind::exact;
    optimum = plan(problem, exact).time_s;
  }
  std::vector<Outcome> outcomes;
  const std::vector<RouteLayer> layers = compared_routes(problem, seed);
  for (std::size_t k = 0; k < layers.size(); ++k) {
    const PlannerKind kind = kCompared[k];
    const Route& route = layers[k].route;
    PlannerOptions planner;
    planner.kind = kind;
    planner.seed = seed;
    Outcome o{route.planner, route.time_s, route.length_m, route.plan_ms, {}, {}};
    if (optimum) {
      planner.sweep = false;  // the exact optimum visits every ball at its centre
      o.gap_to_optimal_pct = gap_pct(plan(problem, planner).time_s, *optimum);
      planner.sweep = true;
    }
    if (kind == PlannerKind::ballsight && (n == 50 || n == 100)) {
      planner.effort = options.long_run_effort;
      o.gap_to_long_run_pct = gap_pct(route.time_s, plan(problem, planner).time_s);
    }
    outcomes.push_back(o);
  }
  if (!plot_name.empty() && options.plot_dir) {
    write_png_atomic(
        *options.plot_dir / (plot_name + ".png"),
        draw_route_map(problem, court_floor(sim::TennisCourtSpec{}), layers, plot_name));
  }
  // The ways of letting the 70 cm collector take several balls at once, measured: ballsight's
  // sweeping (above), every ball's centre visited, or the world model's collection sites
  // (section 7.8 of the report) visited at their centres.
  PlannerOptions centres;
  centres.seed = seed;
  centres.sweep = false;
  const Route every = plan(problem, centres);
  outcomes.push_back({"ballsight_centres", every.time_s, every.length_m, every.plan_ms, {}, {}});
  PlanningProblem sites = problem;
  sites.balls.clear();
  for (const CollectionSite& site : collection_sites(problem.balls, problem.collector_width_m)) {
    sites.balls.push_back(site.center_m);
  }
  const Route by_site = plan(sites, centres);
  outcomes.push_back(
      {"ballsight_sites", by_site.time_s, by_site.length_m, by_site.plan_ms, {}, {}});
  return outcomes;
}

nlohmann::json by_n_json(const std::map<int, PlannerFigures>& by_n) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [n, f] : by_n) {
    nlohmann::json j{{"time_s_mean", f.time_s.mean},     {"time_s_max", f.time_s.max},
                     {"length_m_mean", f.length_m.mean}, {"length_m_max", f.length_m.max},
                     {"plan_ms_mean", f.plan_ms.mean},   {"trials", f.time_s.count}};
    if (f.gap_to_optimal_pct.count > 0) {
      j["gap_to_optimal_pct_mean"] = f.gap_to_optimal_pct.mean;
      j["gap_to_optimal_pct_max"] = f.gap_to_optimal_pct.max;
    }
    if (f.gap_to_long_run_pct.count > 0) {
      j["gap_to_long_run_pct_mean"] = f.gap_to_long_run_pct.mean;
      j["gap_to_long_run_pct_max"] = f.gap_to_long_run_pct.max;
    }
    out[std::to_string(n)] = j;
  }
  return out;
}

}  // namespace

ReportTable plan_comparison(BallLayout layout, int n, std::uint64_t seed,
                            const std::filesystem::path& png) {
  const PlanningProblem problem = court_planning_problem(layout, n, seed);
  const std::vector<RouteLayer> layers = compared_routes(problem, seed);
  const std::string title =
      std::to_string(n) + " balls, layout " + std::string(layout_name(layout));
  write_png_atomic(png,
                   draw_route_map(problem, court_floor(sim::TennisCourtSpec{}), layers, title));
  ReportTable table{title, {"planner", "time (s)", "length (m)", "planned in (ms)"}, {}};
  for (const RouteLayer& layer : layers) {
    const Route& r = layer.route;
    table.rows.push_back(
        {r.planner, fixed(r.time_s, 1), fixed(r.length_m, 1), fixed(r.plan_ms, 2)});
  }
  return table;
}

void Spread::add(double value) {
  mean = (mean * count + value) / (count + 1);
  max = count == 0 ? value : std::max(max, value);
  ++count;
}

void PlanEvalOptions::validate() const {
  require(!sizes.empty() && !layouts.empty(), "eval plan", "needs at least one size and layout");
  for (const int n : sizes) {
    require(n >= 1 && n <= 2000, "eval plan sizes", "each in [1, 2000], got " + std::to_string(n));
  }
  require(long_run_effort > 0.0, "eval plan long_run_effort", "must be positive");
}

int plan_eval_trials(int n) {
  if (n <= 12) return 10;
  if (n <= 100) return 5;
  return 2;
}

PlanEvalReport run_plan_eval(const PlanEvalOptions& options) {
  options.validate();
  if (options.plot_dir) ensure_directory(*options.plot_dir);
  PlanEvalReport report;
  report.options = options;
  for (const BallLayout layout : options.layouts) {
    const std::string layout_key(layout_name(layout));
    for (const int n : options.sizes) {
      for (int t = 0; t < plan_eval_trials(n); ++t) {
        const std::uint64_t seed = options.seed * 1000003ULL + static_cast<std::uint64_t>(n) * 101 +
                                   static_cast<std::uint64_t>(t);
        const PlanningProblem problem = court_planning_problem(layout, n, seed);
        const std::string plot = t == 0 && (n == 20 || n == 50 || n == 100)
                                     ? "plan_" + layout_key + "_" + std::to_string(n)
                                     : "";
        for (const Outcome& o : evaluate(problem, options, seed, plot)) {
          add(report.by_n[o.planner][n], o);
          add(report.by_layout[layout_key][o.planner][n], o);
        }
      }
    }
  }
  return report;
}

nlohmann::json plan_eval_json(const PlanEvalReport& report) {
  nlohmann::json j;
  j["seed"] = report.options.seed;
  j["planners"] = nlohmann::json::object();
  for (const auto& [name, by_n] : report.by_n) j["planners"][name]["by_n"] = by_n_json(by_n);
  for (const auto& [layout, planners] : report.by_layout) {
    for (const auto& [name, by_n] : planners) j["layouts"][layout][name]["by_n"] = by_n_json(by_n);
  }
  // ballsight's mean route time saved against each baseline, per n.
  const auto& ours = report.by_n.at("ballsight");
  for (const char* baseline : {"priority", "nearest"}) {
    for (const auto& [n, f] : report.by_n.at(baseline)) {
      j["ballsight_time_saved_pct"][baseline][std::to_string(n)] =
          100.0 * (1.0 - ours.at(n).time_s.mean / f.time_s.mean);
    }
  }
  return with_wall_clock_apart(std::move(j), {"plan_ms_mean"});
}

std::string plan_eval_text(const PlanEvalReport& report) {
  std::string out = "eval plan (seed " + std::to_string(report.options.seed) +
                    "): layouts uniform, practice, net; time cost, net included\n";
  char line[256];
  for (const auto& [n, ours] : report.by_n.at("ballsight")) {
    std::snprintf(line, sizeof line, "\nn = %d (%d trials per layout)\n", n, plan_eval_trials(n));
    out += line;
    out += "  planner             time mean  time max  length mean  gap to optimum  plan ms\n";
    for (const char* name :
         {"priority", "nearest", "ballsight", "ballsight_centres", "ballsight_sites"}) {
      const PlannerFigures& f = report.by_n.at(name).at(n);
      std::string gap = "-";
      if (f.gap_to_optimal_pct.count > 0) {
        std::snprintf(line, sizeof line, "%.2f%% (max %.2f%%)", f.gap_to_optimal_pct.mean,
                      f.gap_to_optimal_pct.max);
        gap = line;
      }
      std::snprintf(line, sizeof line, "  %-17s %9.1f s %8.1f s %10.1f m  %-16s %7.2f\n", name,
                    f.time_s.mean, f.time_s.max, f.length_m.mean, gap.c_str(), f.plan_ms.mean);
      out += line;
    }
    std::snprintf(line, sizeof line,
                  "  ballsight saves %.1f%% against priority, %.1f%% against nearest",
                  100.0 * (1.0 - ours.time_s.mean / report.by_n.at("priority").at(n).time_s.mean),
                  100.0 * (1.0 - ours.time_s.mean / report.by_n.at("nearest").at(n).time_s.mean));
    out += line;
    if (ours.gap_to_long_run_pct.count > 0) {
      std::snprintf(line, sizeof line, "; %.2f%% above a long run (max %.2f%%)",
                    ours.gap_to_long_run_pct.mean, ours.gap_to_long_run_pct.max);
      out += line;
    }
    out += "\n";
  }
  return out;
}

}  // namespace ballsight::eval
