// `ballsight eval tsplib`: the route planner as a plain shortest-tour solver on TSPLIB instances
// with published optima (by default the ones Debian's glpk-utils ships).

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/plan/planner.hpp"
#include "ballsight/plan/tsplib.hpp"
#include "commands.hpp"
#include "option_parsing.hpp"

namespace ballsight::app {
namespace {

struct EvalTsplibArgs {
  std::string dir = eval::kGlpkTspDir.string();
  PlannerOptions options;
  bool json = false;
};

void run_eval_tsplib(const EvalTsplibArgs& args) {
  const std::filesystem::path dir = args.dir;
  const auto optima = eval::parse_tsplib_optima(read_file(dir / "bench.txt"));
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() == ".tsp") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  nlohmann::json out = nlohmann::json::array();
  for (const auto& file : files) {
    const eval::TsplibInstance instance = eval::read_tsplib(file);
    const auto optimum = optima.find(instance.name);
    if (optimum == optima.end()) continue;
    const auto started = std::chrono::steady_clock::now();
    const std::vector<int> tour = shortest_tour(instance.cost, args.options);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started)
            .count();
    const double length = eval::tour_length(instance, tour);
    out.push_back({{"instance", instance.name},
                   {"n", instance.cost.size()},
                   {"optimum", optimum->second},
                   {"length", length},
                   {"gap_pct", 100.0 * (length / optimum->second - 1.0)},
                   {"plan_ms", ms}});
  }
  require(!out.empty(), dir.string(), "no .tsp instance with an optimum in bench.txt");
  if (args.json) {
    std::cout << out.dump(2) << "\n";
    return;
  }
  std::printf("instance     n   optimum    length     gap   plan ms\n");
  for (const auto& r : out) {
    std::printf("%-10s %4d %9.0f %9.0f %6.2f%% %8.2f\n", r["instance"].get<std::string>().c_str(),
                r["n"].get<int>(), r["optimum"].get<double>(), r["length"].get<double>(),
                r["gap_pct"].get<double>(), r["plan_ms"].get<double>());
  }
}

}  // namespace

void add_eval_tsplib_command(CLI::App& eval) {
  auto args = std::make_shared<EvalTsplibArgs>();
  CLI::App* cmd = eval.add_subcommand(
      "tsplib",
      "ballsight's route search as a plain shortest-tour solver on TSPLIB instances against their "
      "published optima (GLPK's bench.txt beside them)");
  cmd->add_option("--dir", args->dir, "Folder of .tsp files and bench.txt")->capture_default_str();
  cmd->add_option("--effort", args->options.effort, "Search effort, [0, 10000]")
      ->capture_default_str();
  add_seed_option(*cmd, args->options.seed, "Seed of the search's kicks");
  cmd->add_flag("--json", args->json,
                "JSON: [{\"instance\", \"n\", \"optimum\", \"length\", \"gap_pct\", \"plan_ms\"}]");
  cmd->callback([args] { run_eval_tsplib(*args); });
}

}  // namespace ballsight::app
