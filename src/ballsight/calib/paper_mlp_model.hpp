#pragma once
// The omnivision paper's method (Section III-B): normalise (Eq. 2-4), a 2-36-36-1 sigmoid MLP
// trained on MSE, denormalise (Eq. 6); the direction is the image direction (Algorithm 5).
// Trained with OpenCV's cv::ml::ANN_MLP; evaluated here from its weights.

#include <Eigen/Core>
#include <span>
#include <vector>

#include "ballsight/calib/omni_ground_model.hpp"

namespace ballsight {

struct PaperMlpFitOptions {
  int hidden_layers = 2;
  int hidden_neurons = 36;
  int max_epochs = 300000;  // the paper trains 300000 epochs; here an upper bound
  /// Training runs in blocks of about `updates_per_block` sample presentations (2000 epochs of
  /// the paper's ~320 markers; more epochs for fewer samples); after each block the training
  /// MSE is checked, and training stops once `patience_blocks` blocks in a row improved the
  /// best MSE by less than `min_improvement` (relative). The best weights seen are kept.
  int updates_per_block = 640000;
  int patience_blocks = 5;
  double min_improvement = 0.005;
  /// OpenCV's BACKPROP (online gradient descent with momentum) by default. RPROP converges
  /// 8x faster, but its steep sigmoids spike between marker rings: on the paper's marker layout
  /// held-out distance p95 17 cm against 5 cm, worst ground point 193 cm against 15 cm
  /// (bench/omni_fit.cpp, docs/omni-calibration.md), so it is not the default.
  bool use_rprop = false;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// How training went.
struct PaperMlpTraining {
  int epochs = 0;             // epochs run
  double training_mse = 0.0;  // of the normalised distance, with the kept weights
};

/// The paper's normalisation. Eq. 2 as printed, (theta - 1) / 180, contradicts Table II (0 deg
/// -> -1, 10 deg -> -0.94, 350 deg -> 0.94); Table II is theta / 180 - 1, used here.
inline double paper_normalised_direction(double theta_deg) {
  return theta_deg / 180.0 - 1.0;
}
inline double paper_normalised_radius(double radius_px) {
  return radius_px / 160.0 - 1.0;  // Eq. 3
}
inline double paper_normalised_distance(double distance_cm) {
  return distance_cm / 600.0 - 1.0;  // Eq. 4
}
inline double paper_denormalised_distance(double normalised) {
  return normalised * 600.0 + 600.0;  // Eq. 6
}

/// One fully connected layer with OpenCV's symmetric sigmoid
/// f(y) = beta (1 - e^(-alpha y)) / (1 + e^(-alpha y)); alpha = beta = 1 is 2 / (1 + e^-y) - 1,
/// the paper's logistic sigmoid (Eq. 5) scaled to (-1, 1) so it reaches the normalised targets.
struct MlpLayer {
  Eigen::MatrixXd weights;  // outputs x inputs
  Eigen::VectorXd bias;
};

struct PaperMlpNetwork {
  std::vector<MlpLayer> layers;
  double alpha = 1.0;
  double beta = 1.0;

  /// Normalised (direction, radius) -> normalised distance.
  double evaluate(double normalised_direction, double normalised_radius) const;
};

class PaperMlpGroundModel final : public OmniGroundModel {
 public:
  PaperMlpGroundModel(PaperMlpNetwork network, const OmniModelDomain& domain,
                      const PaperMlpTraining& training = {});

  static PaperMlpGroundModel from_parameters_json(const nlohmann::json& parameters,
                                                  const OmniModelDomain& domain);

  std::string_view name() const override { return "paper-mlp"; }
  const OmniModelDomain& domain() const override { return domain_; }
  GroundPrediction predict(double theta_deg, double radius_px) const override;
  nlohmann::json parameters_json() const override;

  const PaperMlpNetwork& network() const { return network_; }
  const PaperMlpTraining& training() const { return training_; }

 private:
  PaperMlpNetwork network_;
  OmniModelDomain domain_;
  PaperMlpTraining training_;
};

/// Trains the paper's network on the samples (their bearings are ignored, as in the paper).
/// Throws InputError when there are fewer than 8 samples.
PaperMlpGroundModel fit_paper_mlp_model(std::span<const PolarSample> samples,
                                        const OmniImage& image,
                                        const PaperMlpFitOptions& options = {});

}  // namespace ballsight
