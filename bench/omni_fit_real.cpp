// The omni models on real data (../shared/data; a benchmark is skipped when it is absent):
//  - Table I of the omnivision paper, 17 measured rows: leave-one-out distance error (loo_*).
//  - The IRIS robots' px2cm tables: the distance profile of a real mirror (their network's
//    output inside its trained range). Markers are placed where a table reaches 60 .. 460 cm
//    (every 50 cm, every 10 deg); held out are 5000 random (theta, radius) where the table is
//    monotone up to the radius and reads 60 .. 460 cm (heldout_dist_*; the table's 1 cm and
//    0.1 px rounding stays in the error). Direction cannot be scored: the tables hold distance
//    only.
// The time is that of all the fits of one benchmark iteration.

#include <benchmark/benchmark.h>

#include <filesystem>
#include <random>
#include <string>

#include "ballsight/calib/ground_error.hpp"
#include "ballsight/calib/omni_model_fit.hpp"
#include "ballsight/calib/sample_csv.hpp"
#include "ballsight/camera/iris_lut.hpp"

namespace ballsight {
namespace {

namespace fs = std::filesystem;

const fs::path kData = BALLSIGHT_SHARED_DATA_DIR;

void report(benchmark::State& state, const std::string& prefix, std::vector<double> errors) {
  const ErrorSummary e = summarize_errors(std::move(errors));
  state.counters[prefix + "median_cm"] = e.median;
  state.counters[prefix + "mean_cm"] = e.mean;
  state.counters[prefix + "p95_cm"] = e.p95;
  state.counters[prefix + "max_cm"] = e.max;
}

// `without_110cm`: leave out the four 110 cm rows, three of which (~105 px) no smooth mirror
// profile through the 60 and 160 cm rows reaches (docs/omni-calibration.md).
void leave_one_out_table1(benchmark::State& state, OmniMethod method,
                          const OmniFitOptions& options = {}, bool without_110cm = false) {
  const fs::path path = kData / "paper-tables" / "table1_training_samples.csv";
  if (!fs::exists(path)) {
    state.SkipWithError(("no " + path.string()).c_str());
    return;
  }
  std::vector<PolarSample> samples = read_polar_samples_csv(path);
  if (without_110cm) {
    std::erase_if(samples, [](const PolarSample& s) { return s.distance_cm == 110.0; });
  }
  const OmniImage image = omni_image_for_samples(samples, std::nullopt, std::nullopt);
  std::vector<double> errors;
  for (auto _ : state) {
    errors.clear();
    for (std::size_t i = 0; i < samples.size(); ++i) {
      std::vector<PolarSample> others = samples;
      others.erase(others.begin() + static_cast<std::ptrdiff_t>(i));
      const auto model = fit_omni_model(method, others, image, options);
      errors.push_back(
          std::abs(model->predict(samples[i].theta_deg, samples[i].radius_px).distance_cm -
                   samples[i].distance_cm));
    }
  }
  report(state, "loo_", errors);
}

struct IrisProfile {
  std::vector<PolarSample> markers;
  std::vector<std::pair<Vec2, double>> held_out;  // (theta_deg, radius_px), distance_cm
};

// The radius where the table's ray at bin centre theta + 0.5 first reads at least `cm`.
std::optional<double> radius_reaching(const IrisLut& lut, int theta, double cm) {
  for (int bin = 500; bin < 2500; ++bin) {
    const auto d = iris_distance_cm(lut, theta + 0.5, (bin + 0.5) / 10.0);
    if (d && *d >= cm) return (bin + 0.5) / 10.0;
  }
  return std::nullopt;
}

// Whether the ray's distance never drops from 50 px to `radius_px`.
bool monotone_until(const IrisLut& lut, double theta_deg, double radius_px) {
  int previous = 0;
  for (double r = 50.05; r <= radius_px; r += 0.1) {
    const int d = iris_distance_cm(lut, theta_deg, r).value_or(0);
    if (d < previous) return false;
    previous = d;
  }
  return true;
}

IrisProfile iris_profile(const IrisLut& lut) {
  IrisProfile profile;
  for (int theta = 0; theta < 360; theta += 10) {
    for (double cm = 60.0; cm <= 460.0; cm += 50.0) {
      if (const auto r = radius_reaching(lut, theta, cm)) {
        profile.markers.push_back({theta + 0.5, *r, cm, std::nullopt});
      }
    }
  }
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> theta(0.0, 360.0), radius(50.0, 250.0);
  while (profile.held_out.size() < 5000) {
    const Vec2 query(theta(rng), radius(rng));
    const auto d = iris_distance_cm(lut, query.x(), query.y());
    if (d && *d >= 60 && *d <= 460 && monotone_until(lut, query.x(), query.y())) {
      profile.held_out.push_back({query, *d});
    }
  }
  return profile;
}

void fit_iris_profile(benchmark::State& state, const std::string& table, OmniMethod method,
                      const OmniFitOptions& options = {}) {
  const fs::path path = kData / "iris-lut" / table;
  if (!fs::exists(path)) {
    state.SkipWithError(("no " + path.string()).c_str());
    return;
  }
  const IrisProfile profile = iris_profile(read_iris_lut(path, IrisLutKind::px2cm));
  std::unique_ptr<OmniGroundModel> model;
  for (auto _ : state) model = fit_omni_model(method, profile.markers, {}, options);
  std::vector<double> errors;
  for (const auto& [query, cm] : profile.held_out) {
    errors.push_back(std::abs(model->predict(query.x(), query.y()).distance_cm - cm));
  }
  state.counters["markers"] = static_cast<double>(profile.markers.size());
  report(state, "heldout_dist_", errors);
}

OmniFitOptions ballsight_distortion(int terms) {
  OmniFitOptions options;
  options.ballsight.distortion_terms = terms;
  return options;
}

void BM_LeaveOneOutTableIPoly(benchmark::State& state) {
  leave_one_out_table1(state, OmniMethod::kPoly);
}
BENCHMARK(BM_LeaveOneOutTableIPoly)->Unit(benchmark::kMillisecond);

void BM_LeaveOneOutTableIPaperMlp(benchmark::State& state) {
  leave_one_out_table1(state, OmniMethod::kPaperMlp);
}
BENCHMARK(BM_LeaveOneOutTableIPaperMlp)->Unit(benchmark::kSecond)->Iterations(1);

void BM_LeaveOneOutTableIBallsight(benchmark::State& state) {
  leave_one_out_table1(state, OmniMethod::kBallsight);
}
BENCHMARK(BM_LeaveOneOutTableIBallsight)->Unit(benchmark::kMillisecond);

void BM_LeaveOneOutTableIBallsightDistortion1(benchmark::State& state) {
  leave_one_out_table1(state, OmniMethod::kBallsight, ballsight_distortion(1));
}
BENCHMARK(BM_LeaveOneOutTableIBallsightDistortion1)->Unit(benchmark::kMillisecond);

void BM_LeaveOneOutTableIBallsightDistortion2(benchmark::State& state) {
  leave_one_out_table1(state, OmniMethod::kBallsight, ballsight_distortion(2));
}
BENCHMARK(BM_LeaveOneOutTableIBallsightDistortion2)->Unit(benchmark::kMillisecond);

void BM_LeaveOneOutTableIWithout110cmPoly(benchmark::State& state) {
  leave_one_out_table1(state, OmniMethod::kPoly, {}, true);
}
BENCHMARK(BM_LeaveOneOutTableIWithout110cmPoly)->Unit(benchmark::kMillisecond);

void BM_LeaveOneOutTableIWithout110cmBallsight(benchmark::State& state) {
  leave_one_out_table1(state, OmniMethod::kBallsight, {}, true);
}
BENCHMARK(BM_LeaveOneOutTableIWithout110cmBallsight)->Unit(benchmark::kMillisecond);

// One benchmark per table and method: iris2 and iris3, poly / ballsight (and its candidates).
void BM_IrisProfile(benchmark::State& state, const std::string& table, OmniMethod method,
                    int distortion_terms) {
  fit_iris_profile(state, table, method, ballsight_distortion(distortion_terms));
}
BENCHMARK_CAPTURE(BM_IrisProfile, iris2Poly, "iris2_px2cm_main.bin", OmniMethod::kPoly, 0)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_IrisProfile, iris2Ballsight, "iris2_px2cm_main.bin", OmniMethod::kBallsight, 0)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_IrisProfile, iris2BallsightDistortion2, "iris2_px2cm_main.bin",
                  OmniMethod::kBallsight, 2)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_IrisProfile, iris3Poly, "iris3_px2cm.bin", OmniMethod::kPoly, 0)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_IrisProfile, iris3Ballsight, "iris3_px2cm.bin", OmniMethod::kBallsight, 0)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_IrisProfile, iris3BallsightDistortion2, "iris3_px2cm.bin",
                  OmniMethod::kBallsight, 2)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_IrisProfile, iris3PaperMlp, "iris3_px2cm.bin", OmniMethod::kPaperMlp, 0)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

}  // namespace
}  // namespace ballsight

BENCHMARK_MAIN();
