#include "ballsight/calib/model_json.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <random>

#include "ballsight/calib/omni_model_fit.hpp"
#include "ballsight/core/file_io.hpp"
#include "calib/calib_fixtures.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

std::vector<PolarSample> simulated_samples() {
  const OmniRig rig(test::paper_misaligned_rig());
  SimulatedCalibrationOptions markers = test::paper_markers(3);
  markers.rays = 12;
  return simulate_calibration(rig, markers).samples;
}

// Every method: save, load, and the loaded model predicts exactly as the fitted one.
TEST(ModelJson, RoundTripPredictsIdentically) {
  const test::TempDir dir;
  OmniFitOptions options;
  options.paper_mlp.max_epochs = 200;
  for (const OmniMethod method :
       {OmniMethod::kPoly, OmniMethod::kPaperMlp, OmniMethod::kBallsight}) {
    SCOPED_TRACE(omni_method_name(method));
    const auto model = fit_omni_model(method, simulated_samples(), {}, options);
    save_omni_model(dir / "model.json", *model);
    const auto loaded = load_omni_model(dir / "model.json");
    EXPECT_EQ(loaded->name(), model->name());
    EXPECT_EQ(loaded->domain().valid_radius.min_px, model->domain().valid_radius.min_px);
    EXPECT_EQ(loaded->domain().valid_radius.max_px, model->domain().valid_radius.max_px);
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> theta(0.0, 360.0), radius(50.0, 260.0);
    for (int i = 0; i < 200; ++i) {
      const double t = theta(rng), r = radius(rng);
      const GroundPrediction a = model->predict(t, r), b = loaded->predict(t, r);
      EXPECT_TRUE(a.distance_cm == b.distance_cm ||
                  (std::isnan(a.distance_cm) && std::isnan(b.distance_cm)))
          << t << " deg, " << r << " px";
      EXPECT_EQ(a.bearing_deg, b.bearing_deg);
      EXPECT_EQ(a.in_range, b.in_range);
    }
  }
}

TEST(ModelJson, BadDocumentsNameTheFileAndField) {
  const test::TempDir dir;
  const auto model = fit_omni_model(OmniMethod::kPoly, simulated_samples(), {});
  const nlohmann::json good = omni_model_to_json(*model);
  struct Case {
    std::function<void(nlohmann::json&)> damage;
    std::string expected;
  };
  const Case cases[] = {
      {[](nlohmann::json& j) { j["format"] = "something"; }, "model.format"},
      {[](nlohmann::json& j) { j["version"] = 9; }, "model.version: expected 1"},
      {[](nlohmann::json& j) { j["method"] = "magic"; }, "model.method: unknown method 'magic'"},
      {[](nlohmann::json& j) { j["image"].erase("width"); }, "image.width: missing"},
      {[](nlohmann::json& j) {
         j["image"]["center_px"] = {1e6, 3};
       },
       "image centre"},
      {[](nlohmann::json& j) {
         j["valid_radius_px"] = {100, 50};
       },
       "model.valid_radius_px"},
      {[](nlohmann::json& j) { j["parameters"]["coefficients"][2] = "x"; },
       "parameters.coefficients: expected an array of 7 finite numbers"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.expected);
    nlohmann::json damaged = good;
    c.damage(damaged);
    write_file_atomic(dir / "m.json", damaged.dump());
    const std::string message = test::input_error([&] { load_omni_model(dir / "m.json"); });
    EXPECT_EQ(message.rfind((dir / "m.json").string() + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(c.expected), std::string::npos) << message;
  }
  write_file_atomic(dir / "m.json", "{ not json");
  EXPECT_NE(test::input_error([&] { load_omni_model(dir / "m.json"); }).find("not valid JSON"),
            std::string::npos);
}

}  // namespace
}  // namespace ballsight
