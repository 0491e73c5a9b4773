#include "ballsight/eval/omni_real.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <deque>
#include <exception>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

#include "ballsight/calib/omni_model_fit.hpp"
#include "ballsight/calib/sample_csv.hpp"
#include "ballsight/core/csv_fields.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/core/text_format.hpp"
#include "ballsight/eval/omni_data_floor.hpp"

namespace ballsight {

namespace fs = std::filesystem;

namespace {

// MinhoTeam's measured-looking mirror profiles (the folder's README: 1 is a placeholder, 2 an
// edited copy of 0, 5 a "Teste" of one robot with 8 entries, too few to hold one out for every
// method). One direction: the team uses one profile for all.
constexpr int kMinhoProfiles[] = {0, 3, 4};
constexpr double kMinhoTheta = 90.0;

// profile -> samples, from MinhoTeam's `profile,...,distance_m,radius_px` file.
std::map<int, std::vector<PolarSample>> read_minho_profiles(const fs::path& path) {
  std::istringstream text(read_file(path));
  std::string line;
  std::getline(text, line);
  require(line.starts_with("profile,") && line.ends_with("distance_m,radius_px"),
          path.string() + ":1", "expected the header profile,...,distance_m,radius_px");
  std::map<int, std::vector<PolarSample>> profiles;
  for (int number = 2; std::getline(text, line); ++number) {
    if (trim_blanks(line).empty()) continue;
    const std::vector<CsvField> fields = split_csv_fields(line);
    const std::string where = path.string() + ":" + std::to_string(number);
    require(fields.size() == 8, where, "expected 8 columns, got " + std::to_string(fields.size()));
    const double profile = csv_number(fields[0], where);
    const double distance_m = csv_number(fields[6], where);
    const double radius_px = csv_number(fields[7], where);
    require(distance_m > 0.0 && radius_px > 0.0, where, "expected a positive distance and radius");
    profiles[static_cast<int>(profile)].push_back(
        {kMinhoTheta, radius_px, 100.0 * distance_m, std::nullopt});
  }
  return profiles;
}

// Fits `method` on each of `folds` (of `split`) and scores its held-out samples.
HeldOutScore score_method(const RealOmniSet& set, const std::string& method, HeldOutSplit split,
                          std::span<const HeldOutFold> folds) {
  HeldOutScore score{method, split, {}, 0, 0.0};
  std::vector<double> errors;
  for (const auto& [train, test] : folds) {
    const auto start = std::chrono::steady_clock::now();
    const auto model = fit_omni_model(parse_omni_method(method), train, set.image);
    score.fit_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (const PolarSample& s : test) {
      const double d = model->predict(s.theta_deg, s.radius_px).distance_cm;
      errors.push_back(held_out_error_cm(std::isfinite(d) ? std::optional<double>(d) : std::nullopt,
                                         s, score.unmapped));
    }
  }
  score.distance_cm = summarize_errors(std::move(errors));
  return score;
}

}  // namespace

std::vector<RealOmniSet> load_real_omni_sets(const fs::path& data_dir,
                                             std::vector<std::string>& missing) {
  std::vector<RealOmniSet> sets;
  const auto add_csv = [&](const std::string& name, const fs::path& file,
                           std::optional<Vec2> center, std::optional<Eigen::Vector2i> size) {
    const fs::path path = data_dir / file;
    if (!fs::exists(path)) {
      missing.push_back(path.string());
      return;
    }
    std::vector<PolarSample> samples = read_polar_samples_csv(path);
    const OmniImage image = omni_image_for_samples(samples, center, size);
    sets.push_back({name, std::move(samples), image});
  };
  // Image sizes and centres from each folder's README.
  add_csv("tribots-2005", "real/omni/tribots-2005/samples_0.5-4m.csv", Vec2(299.0, 209.0),
          Eigen::Vector2i(640, 480));
  add_csv("cnc-msl-nase-2016-03",
          "real/omni/cnc-msl-nase-2016-03/samples_nase_2016-03-30_rings1-3m.csv",
          Vec2(230.0, 230.0), Eigen::Vector2i(460, 460));
  const fs::path minho = data_dir / "real/omni/minhoteam/mirror_profiles.csv";
  if (fs::exists(minho)) {
    const auto profiles = read_minho_profiles(minho);
    for (const int profile : kMinhoProfiles) {
      const auto found = profiles.find(profile);
      require(found != profiles.end(), minho.string(), "has no profile " + std::to_string(profile));
      sets.push_back(
          {"minhoteam-profile-" + std::to_string(profile), found->second,
           omni_image_for_samples(found->second, Vec2(240.0, 240.0), Eigen::Vector2i(480, 480))});
    }
  } else {
    missing.push_back(minho.string());
  }
  add_csv("table-1", "paper-tables/table1_training_samples.csv", std::nullopt, std::nullopt);
  return sets;
}

const HeldOutScore* RealOmniSetResult::find(std::string_view method, HeldOutSplit split) const {
  for (const HeldOutScore& score : scores) {
    if (score.method == method && score.split == split) return &score;
  }
  return nullptr;
}

void OmniRealOptions::validate() const {
  require(!methods.empty(), "methods", "expected at least one method");
  for (const std::string& method : methods) parse_omni_method(method, "methods");
  require(max_distance_folds >= 2, "max_distance_folds", "expected at least 2");
  require(jobs >= 1 && jobs <= 64, "jobs", "expected 1 to 64");
}

OmniRealResult run_omni_real(const OmniRealOptions& options) {
  options.validate();
  OmniRealResult result;
  const std::vector<RealOmniSet> sets = load_real_omni_sets(options.data_dir, result.missing);
  struct Task {
    std::size_t set;
    HeldOutSplit split;
    std::string method;
    const std::vector<HeldOutFold>* folds;
    HeldOutScore score;
  };
  std::vector<Task> tasks;
  std::deque<std::vector<HeldOutFold>> folds_of;  // per set and split: the same for every method
  for (std::size_t i = 0; i < sets.size(); ++i) {
    RealOmniSetResult& out = result.sets.emplace_back();
    out.name = sets[i].name;
    out.samples = sets[i].samples.size();
    out.directions = sample_directions(sets[i].samples).size();
    out.distances_cm = sample_distances(sets[i].samples);
    for (const HeldOutSplit split : {HeldOutSplit::kDirections, HeldOutSplit::kDistance}) {
      const std::vector<HeldOutFold>& folds = folds_of.emplace_back(
          spread_folds(held_out_folds(sets[i].samples, split), options.max_distance_folds));
      if (folds.empty()) continue;
      for (const std::string& method : options.methods)
        tasks.push_back({i, split, method, &folds, {}});
      HeldOutScore& floor = out.floors.emplace_back(HeldOutScore{"floor", split, {}, 0, 0.0});
      floor.distance_cm = neighbour_floor(folds, split, floor.unmapped);
    }
  }
  std::atomic<std::size_t> next = 0;
  std::mutex report;
  std::size_t done = 0;
  std::exception_ptr failure;  // the first fit that threw, rethrown once every worker is done
  const auto work = [&] {
    for (std::size_t t = next++; t < tasks.size(); t = next++) {
      Task& task = tasks[t];
      try {
        task.score = score_method(sets[task.set], task.method, task.split, *task.folds);
      } catch (...) {
        const std::lock_guard lock(report);
        if (!failure) failure = std::current_exception();
        next = tasks.size();
        return;
      }
      const std::lock_guard lock(report);
      ++done;
      if (options.progress) {
        options.progress(std::to_string(done) + "/" + std::to_string(tasks.size()) + " " +
                         sets[task.set].name + " " + std::string(held_out_split_name(task.split)) +
                         " " + task.method + ": median " + fixed(task.score.distance_cm.median, 2) +
                         " cm (" + fixed(task.score.fit_seconds, 1) + " s)");
      }
    }
  };
  std::vector<std::thread> workers;
  for (int j = 1; j < options.jobs; ++j) workers.emplace_back(work);
  work();
  for (std::thread& worker : workers) worker.join();
  if (failure) std::rethrow_exception(failure);
  for (Task& task : tasks) result.sets[task.set].scores.push_back(std::move(task.score));
  return result;
}

std::optional<OmniRealTarget> omni_real_target(const RealOmniSetResult& set, HeldOutSplit split) {
  const HeldOutScore* ours = set.find("ballsight", split);
  const HeldOutScore* poly = set.find("poly", split);
  const HeldOutScore* mlp = set.find("paper-mlp", split);
  const auto floor = std::find_if(set.floors.begin(), set.floors.end(),
                                  [&](const HeldOutScore& f) { return f.split == split; });
  if (!ours || !poly || !mlp || floor == set.floors.end()) return std::nullopt;
  OmniRealTarget target;
  target.better_baseline_cm = std::min(poly->distance_cm.median, mlp->distance_cm.median);
  target.floor_cm = floor->distance_cm.median;
  target.ballsight_cm = ours->distance_cm.median;
  if (target.floor_cm < 0.7 * target.better_baseline_cm) {
    target.rule = OmniRealRule::seven_tenths;
    target.limit_cm = 0.7 * target.better_baseline_cm;
  } else if (1.1 * target.floor_cm < target.better_baseline_cm) {
    target.rule = OmniRealRule::floor;
    target.limit_cm = 1.1 * target.floor_cm;
  } else {
    target.rule = OmniRealRule::better_baseline;
    target.limit_cm = target.better_baseline_cm;
  }
  return target;
}

std::string_view omni_real_rule_name(OmniRealRule rule) {
  switch (rule) {
    case OmniRealRule::seven_tenths:
      return "0.7x the better baseline";
    case OmniRealRule::floor:
      return "1.1x the floor";
    case OmniRealRule::better_baseline:
      break;
  }
  return "the better baseline";
}

namespace {

// The JSON row of one score.
nlohmann::json score_json(const HeldOutScore& s) {
  return {{"method", s.method},
          {"split", held_out_split_name(s.split)},
          {"median_cm", s.distance_cm.median},
          {"mean_cm", s.distance_cm.mean},
          {"p95_cm", s.distance_cm.p95},
          {"max_cm", s.distance_cm.max},
          {"count", s.distance_cm.count},
          {"unmapped", s.unmapped},
          {"fit_seconds", s.fit_seconds}};
}

// The table row of one score.
std::string score_row(const std::string& set, const HeldOutScore& s) {
  char line[200];
  std::snprintf(line, sizeof line, "%-22s %-11s %-10s %7.2f %7.2f %7.2f %9zu %7.2f s\n",
                set.c_str(), std::string(held_out_split_name(s.split)).c_str(), s.method.c_str(),
                s.distance_cm.median, s.distance_cm.p95, s.distance_cm.max, s.unmapped,
                s.fit_seconds);
  return line;
}

}  // namespace

nlohmann::json omni_real_json(const OmniRealResult& result) {
  nlohmann::json sets = nlohmann::json::array();
  for (const RealOmniSetResult& set : result.sets) {
    nlohmann::json scores = nlohmann::json::array(), floors = nlohmann::json::array();
    for (const HeldOutScore& s : set.scores) scores.push_back(score_json(s));
    for (const HeldOutScore& s : set.floors) floors.push_back(score_json(s));
    nlohmann::json ratios = nlohmann::json::object(), targets = nlohmann::json::object();
    for (const HeldOutSplit split : {HeldOutSplit::kDirections, HeldOutSplit::kDistance}) {
      const std::string name(held_out_split_name(split));
      if (const auto t = omni_real_target(set, split)) {
        ratios[name] = t->ballsight_cm / t->better_baseline_cm;
        targets[name] = {{"better_baseline_cm", t->better_baseline_cm},
                         {"floor_cm", t->floor_cm},
                         {"ballsight_cm", t->ballsight_cm},
                         {"limit_cm", t->limit_cm},
                         {"rule", omni_real_rule_name(t->rule)},
                         {"met", t->met()}};
      }
    }
    sets.push_back({{"name", set.name},
                    {"samples", set.samples},
                    {"directions", set.directions},
                    {"distances_cm", set.distances_cm},
                    {"scores", scores},
                    {"floor", floors},
                    {"ballsight_over_best_baseline", ratios},
                    {"targets", targets}});
  }
  return {{"sets", sets}, {"missing", result.missing}};
}

std::string omni_real_table(const OmniRealResult& result) {
  std::string out =
      "set                    split       method      median    p95    max (cm)  unmapped  fit\n";
  for (const RealOmniSetResult& set : result.sets) {
    for (const HeldOutScore& s : set.scores) out += score_row(set.name, s);
    for (const HeldOutScore& s : set.floors) out += score_row(set.name, s);
    for (const HeldOutSplit split : {HeldOutSplit::kDirections, HeldOutSplit::kDistance}) {
      const std::string name = set.name + " " + std::string(held_out_split_name(split));
      if (const auto t = omni_real_target(set, split)) {
        out += name + ": ballsight / better baseline = " +
               fixed(t->ballsight_cm / t->better_baseline_cm, 2) + "; target (" +
               std::string(omni_real_rule_name(t->rule)) + ") " + fixed(t->limit_cm, 2) +
               " cm: " + (t->met() ? "met" : "not met") + "\n";
      }
    }
  }
  for (const std::string& path : result.missing) out += "missing (skipped): " + path + "\n";
  return out;
}

}  // namespace ballsight
