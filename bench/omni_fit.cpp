// Fitting the omni pixel -> ground models (calib/omni_model_fit.hpp) to a simulated marker
// calibration of the paper's misaligned rig (1.5 deg tilt, ~5 px centre offset, 1 px clicks),
// and how well each fit does: counters give the held-out error over 5000 random floor points
// at 60 .. 460 cm (heldout_pos_*: ground point error, heldout_dist_*: distance error, cm).
// Only the fit is timed. Candidates for ballsight's model are measured beside the default.

#include <benchmark/benchmark.h>

#include <string>

#include "ballsight/calib/ground_error.hpp"
#include "ballsight/calib/omni_model_fit.hpp"

namespace ballsight {
namespace {

struct Scenario {
  int rings = 10;  // 10 distances x 40 bearings = 400 markers
  int rays = 40;
  int mislabelled = 0;
  bool with_bearing = true;
};

void report_held_out(benchmark::State& state, const OmniRig& rig, const OmniGroundModel& model) {
  const GroundErrors e = ground_errors(model, random_floor_truth(rig, 60.0, 460.0, 5000, 99));
  state.counters["heldout_pos_median_cm"] = e.position_cm.median;
  state.counters["heldout_pos_mean_cm"] = e.position_cm.mean;
  state.counters["heldout_pos_p95_cm"] = e.position_cm.p95;
  state.counters["heldout_pos_max_cm"] = e.position_cm.max;
  state.counters["heldout_dist_median_cm"] = e.distance_cm.median;
  state.counters["heldout_dist_p95_cm"] = e.distance_cm.p95;
  state.counters["out_of_range"] = static_cast<double>(e.out_of_range);
}

void fit_and_report(benchmark::State& state, const Scenario& scenario, OmniMethod method,
                    const OmniFitOptions& options) {
  OmniRigParams params;
  params.tilt_deg = 1.5;
  params.tilt_azimuth_deg = 30.0;
  params.center_offset_px = {4.0, -3.0};
  const OmniRig rig(params);
  SimulatedCalibrationOptions markers;
  markers.rings = scenario.rings;
  markers.rays = scenario.rays;
  markers.mislabelled = scenario.mislabelled;
  markers.with_bearing = scenario.with_bearing;
  markers.seed = 2024;
  const std::vector<PolarSample> samples = simulate_calibration(rig, markers).samples;
  std::unique_ptr<OmniGroundModel> model;
  for (auto _ : state) {
    model = fit_omni_model(method, samples, {}, options);
    benchmark::DoNotOptimize(model.get());
  }
  state.counters["samples"] = static_cast<double>(samples.size());
  report_held_out(state, rig, *model);
}

OmniFitOptions poly_degree(int degree) {
  OmniFitOptions options;
  options.poly.degree = degree;
  return options;
}

OmniFitOptions ballsight_distortion(int terms) {
  OmniFitOptions options;
  options.ballsight.distortion_terms = terms;
  return options;
}

// Plain least squares: the robust losses' widths so large they never bend.
OmniFitOptions ballsight_least_squares() {
  OmniFitOptions options;
  options.ballsight.huber_px = 1e9;
  options.ballsight.min_cauchy_px = 1e9;
  return options;
}

OmniFitOptions paper_mlp_rprop() {
  OmniFitOptions options;
  options.paper_mlp.use_rprop = true;
  return options;
}

constexpr Scenario k400{};
constexpr Scenario k400Mislabelled{10, 40, 5, true};
constexpr Scenario k400DistanceOnly{10, 40, 0, false};
constexpr Scenario kPaperLayout{9, 36, 0, true};  // 60 .. 460 cm every 50 cm, every 10 deg

// The default model and its candidates.
void BM_FitBallsight400(benchmark::State& state) {
  fit_and_report(state, k400, OmniMethod::kBallsight, {});
}
BENCHMARK(BM_FitBallsight400)->Unit(benchmark::kMillisecond);

void BM_FitBallsight400Distortion1(benchmark::State& state) {
  fit_and_report(state, k400, OmniMethod::kBallsight, ballsight_distortion(1));
}
BENCHMARK(BM_FitBallsight400Distortion1)->Unit(benchmark::kMillisecond);

void BM_FitBallsight400Distortion2(benchmark::State& state) {
  fit_and_report(state, k400, OmniMethod::kBallsight, ballsight_distortion(2));
}
BENCHMARK(BM_FitBallsight400Distortion2)->Unit(benchmark::kMillisecond);

void BM_FitBallsight400Mislabelled5(benchmark::State& state) {
  fit_and_report(state, k400Mislabelled, OmniMethod::kBallsight, {});
}
BENCHMARK(BM_FitBallsight400Mislabelled5)->Unit(benchmark::kMillisecond);

void BM_FitBallsight400Mislabelled5LeastSquares(benchmark::State& state) {
  fit_and_report(state, k400Mislabelled, OmniMethod::kBallsight, ballsight_least_squares());
}
BENCHMARK(BM_FitBallsight400Mislabelled5LeastSquares)->Unit(benchmark::kMillisecond);

void BM_FitBallsight400DistanceOnly(benchmark::State& state) {
  fit_and_report(state, k400DistanceOnly, OmniMethod::kBallsight, {});
}
BENCHMARK(BM_FitBallsight400DistanceOnly)->Unit(benchmark::kMillisecond);

void BM_FitBallsightPaperLayout(benchmark::State& state) {
  fit_and_report(state, kPaperLayout, OmniMethod::kBallsight, {});
}
BENCHMARK(BM_FitBallsightPaperLayout)->Unit(benchmark::kMillisecond);

// The paper's baselines.
void BM_FitPoly400(benchmark::State& state) {
  fit_and_report(state, k400, OmniMethod::kPoly, {});
}
BENCHMARK(BM_FitPoly400)->Unit(benchmark::kMicrosecond);

void BM_FitPoly400Degree3(benchmark::State& state) {
  fit_and_report(state, k400, OmniMethod::kPoly, poly_degree(3));
}
BENCHMARK(BM_FitPoly400Degree3)->Unit(benchmark::kMicrosecond);

void BM_FitPaperMlp(benchmark::State& state) {
  fit_and_report(state, k400, OmniMethod::kPaperMlp, {});
}
BENCHMARK(BM_FitPaperMlp)->Unit(benchmark::kSecond)->Iterations(1);

void BM_FitPaperMlpRprop(benchmark::State& state) {
  fit_and_report(state, k400, OmniMethod::kPaperMlp, paper_mlp_rprop());
}
BENCHMARK(BM_FitPaperMlpRprop)->Unit(benchmark::kSecond)->Iterations(1);

void BM_FitPaperMlpPaperLayout(benchmark::State& state) {
  fit_and_report(state, kPaperLayout, OmniMethod::kPaperMlp, {});
}
BENCHMARK(BM_FitPaperMlpPaperLayout)->Unit(benchmark::kSecond)->Iterations(1);

void BM_FitPaperMlpRpropPaperLayout(benchmark::State& state) {
  fit_and_report(state, kPaperLayout, OmniMethod::kPaperMlp, paper_mlp_rprop());
}
BENCHMARK(BM_FitPaperMlpRpropPaperLayout)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
}  // namespace ballsight

BENCHMARK_MAIN();
