#include "ballsight/calib/paper_mlp_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "ballsight/calib/ground_error.hpp"
#include "calib/calib_fixtures.hpp"

namespace ballsight {
namespace {

// Table II of the omnivision paper: (theta, radius, distance) -> normalised (D, E, F), printed
// to two decimals.
TEST(PaperMlp, NormalisationMatchesTableII) {
  struct Row {
    double theta, radius, distance, d, e, f;
  };
  const Row rows[] = {{0, 81, 60, -1, -0.49, -0.90},
                      {0, 143.355, 160, -1, -0.10, -0.73},
                      {10, 171.878, 260, -0.94, 0.07, -0.57},
                      {20, 127.343, 110, -0.89, -0.20, -0.82},
                      {350, 159.797, 210, 0.94, -0.00, -0.65}};
  for (const Row& row : rows) {
    SCOPED_TRACE(row.theta);
    EXPECT_NEAR(paper_normalised_direction(row.theta), row.d, 0.005);
    EXPECT_NEAR(paper_normalised_radius(row.radius), row.e, 0.005);
    EXPECT_NEAR(paper_normalised_distance(row.distance), row.f, 0.005);
    EXPECT_DOUBLE_EQ(paper_denormalised_distance(paper_normalised_distance(row.distance)),
                     row.distance);
  }
}

// The network is OpenCV's SIGMOID_SYM, beta (1 - e^(-alpha y)) / (1 + e^(-alpha y)), per layer.
TEST(PaperMlp, EvaluatesLayersWithTheSymmetricSigmoid) {
  PaperMlpNetwork network;
  network.alpha = 1.0;
  network.beta = 1.0;
  MlpLayer hidden;
  hidden.weights.resize(2, 2);
  hidden.weights << 0.5, -1.0, 2.0, 0.25;
  hidden.bias = Eigen::Vector2d(0.1, -0.3);
  MlpLayer output;
  output.weights.resize(1, 2);
  output.weights << 1.5, -0.7;
  output.bias = Eigen::VectorXd::Constant(1, 0.2);
  network.layers = {hidden, output};
  const auto f = [](double y) { return (1.0 - std::exp(-y)) / (1.0 + std::exp(-y)); };
  const double x0 = 0.3, x1 = -0.6;
  const double h0 = f(0.5 * x0 - 1.0 * x1 + 0.1), h1 = f(2.0 * x0 + 0.25 * x1 - 0.3);
  EXPECT_NEAR(network.evaluate(x0, x1), f(1.5 * h0 - 0.7 * h1 + 0.2), 1e-15);
  // alpha = beta = 1 is the paper's logistic sigmoid scaled to (-1, 1).
  EXPECT_NEAR(f(0.8), 2.0 / (1.0 + std::exp(-0.8)) - 1.0, 1e-15);
}

// Trained on the simulated misaligned rig, the net maps distance well between the markers; a
// broken net (wrong normalisation, unconverged, or spiking between marker rings as RPROP does)
// fails these bounds by far. Its direction is the image direction, so the ground point error
// keeps the misalignment's bearing error.
TEST(PaperMlp, FitsTheSimulatedMisalignedRig) {
  const OmniRig rig(test::paper_misaligned_rig());
  SimulatedCalibrationOptions markers = test::paper_markers(21);
  markers.rays = 18;  // every 20 deg: half the samples, half the training time
  const SimulatedCalibration calibration = simulate_calibration(rig, markers);
  PaperMlpFitOptions options;
  options.max_epochs = 10000;
  const PaperMlpGroundModel model = fit_paper_mlp_model(calibration.samples, {}, options);
  EXPECT_LE(model.training().epochs, options.max_epochs);
  EXPECT_GT(model.training().epochs, 0);
  EXPECT_LT(model.training().training_mse, 2e-4);  // RMS below 8.5 cm (the clicks' ~6 cm)
  std::cout << "paper-mlp: " << model.training().epochs << " epochs, training MSE "
            << model.training().training_mse << "\n";
  const GroundErrors held_out =
      ground_errors(model, random_floor_truth(rig, 60.0, 460.0, 1000, 22));
  EXPECT_LT(held_out.distance_cm.median, 3.5);  // measured 2.2
  EXPECT_LT(held_out.distance_cm.p95, 10.0);    // measured 5.8
  EXPECT_LT(held_out.distance_cm.max, 25.0);    // measured 13.6; RPROP's spikes reach ~1100
  EXPECT_EQ(held_out.out_of_range, 0u);
  std::cout << "paper-mlp held-out distance error: median " << held_out.distance_cm.median
            << " cm, p95 " << held_out.distance_cm.p95 << " cm, max " << held_out.distance_cm.max
            << " cm\n";
  EXPECT_FALSE(model.predict(90.0, 150.0).bearing_deg);
}

TEST(PaperMlp, RejectsTooFewSamples) {
  const std::vector<PolarSample> samples(7, PolarSample{0.0, 100.0, 100.0, {}});
  EXPECT_NE(test::input_error([&] {
              fit_paper_mlp_model(samples, {});
            }).find("paper-mlp needs at least 8 samples, got 7"),
            std::string::npos);
}

}  // namespace
}  // namespace ballsight
