#include "ballsight/calib/paper_mlp_model.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/ml.hpp>
#include <stdexcept>
#include <string>

#include "ballsight/core/error.hpp"
#include "ballsight/core/json_fields.hpp"

namespace ballsight {

namespace {

constexpr std::size_t kMinSamples = 8;

MlpLayer layer_from_opencv(const cv::Mat& w) {
  // OpenCV stores a layer as (inputs + 1) x outputs, the last row being the bias.
  MlpLayer layer;
  layer.weights.resize(w.cols, w.rows - 1);
  layer.bias.resize(w.cols);
  for (int o = 0; o < w.cols; ++o) {
    for (int i = 0; i + 1 < w.rows; ++i) layer.weights(o, i) = w.at<double>(i, o);
    layer.bias(o) = w.at<double>(w.rows - 1, o);
  }
  return layer;
}

PaperMlpNetwork network_from_opencv(const cv::ml::ANN_MLP& mlp, std::size_t layer_count,
                                    double alpha, double beta) {
  PaperMlpNetwork network;
  network.alpha = alpha;
  network.beta = beta;
  for (std::size_t l = 1; l < layer_count; ++l) {
    network.layers.push_back(layer_from_opencv(mlp.getWeights(static_cast<int>(l))));
  }
  return network;
}

double training_mse(const PaperMlpNetwork& network, const cv::Mat& inputs, const cv::Mat& targets) {
  double sum = 0.0;
  for (int i = 0; i < inputs.rows; ++i) {
    const double e =
        network.evaluate(inputs.at<float>(i, 0), inputs.at<float>(i, 1)) - targets.at<float>(i, 0);
    sum += e * e;
  }
  return sum / inputs.rows;
}

// Our evaluation reads OpenCV's weight layout, an implementation detail: check that it gives
// OpenCV's own outputs on the training inputs.
void check_same_as_opencv(const PaperMlpNetwork& network, const cv::ml::ANN_MLP& mlp,
                          const cv::Mat& inputs) {
  cv::Mat outputs;
  mlp.predict(inputs, outputs);
  for (int i = 0; i < inputs.rows; ++i) {
    const double ours = network.evaluate(inputs.at<float>(i, 0), inputs.at<float>(i, 1));
    if (!(std::abs(ours - outputs.at<float>(i, 0)) < 1e-5)) {
      throw std::logic_error("paper-mlp: OpenCV ANN_MLP weight layout not as expected");
    }
  }
}

}  // namespace

void PaperMlpFitOptions::validate() const {
  require(hidden_layers >= 1 && hidden_layers <= 4, "paper-mlp hidden_layers",
          "expected an integer in [1, 4]");
  require(hidden_neurons >= 2 && hidden_neurons <= 256, "paper-mlp hidden_neurons",
          "expected an integer in [2, 256]");
  require(max_epochs >= 1, "paper-mlp max_epochs", "expected a positive integer");
  require(updates_per_block >= 1, "paper-mlp updates_per_block", "expected a positive integer");
  require(patience_blocks >= 1, "paper-mlp patience_blocks", "expected a positive integer");
  require(std::isfinite(min_improvement) && min_improvement >= 0.0 && min_improvement < 1.0,
          "paper-mlp min_improvement", "expected a number in [0, 1)");
}

double PaperMlpNetwork::evaluate(double normalised_direction, double normalised_radius) const {
  Eigen::VectorXd x(2);
  x << normalised_direction, normalised_radius;
  for (const MlpLayer& layer : layers) {
    const Eigen::VectorXd y = layer.weights * x + layer.bias;
    x = beta * (0.5 * alpha * y.array()).tanh();  // == beta (1 - e^-ay) / (1 + e^-ay)
  }
  return x(0);
}

PaperMlpGroundModel::PaperMlpGroundModel(PaperMlpNetwork network, const OmniModelDomain& domain,
                                         const PaperMlpTraining& training)
    : network_(std::move(network)), domain_(domain), training_(training) {}

GroundPrediction PaperMlpGroundModel::predict(double theta_deg, double radius_px) const {
  const double normalised =
      network_.evaluate(paper_normalised_direction(theta_deg), paper_normalised_radius(radius_px));
  return {paper_denormalised_distance(normalised), std::nullopt,
          domain_.contains(theta_deg, radius_px)};
}

nlohmann::json PaperMlpGroundModel::parameters_json() const {
  nlohmann::json layers = nlohmann::json::array();
  for (const MlpLayer& layer : network_.layers) {
    nlohmann::json rows = nlohmann::json::array();
    for (Eigen::Index o = 0; o < layer.weights.rows(); ++o) {
      const Eigen::VectorXd row = layer.weights.row(o).transpose();
      rows.push_back(std::vector<double>(row.data(), row.data() + row.size()));
    }
    layers.push_back(
        {{"weights", rows},
         {"bias", std::vector<double>(layer.bias.data(), layer.bias.data() + layer.bias.size())}});
  }
  return {{"activation", "sigmoid_sym"},
          {"alpha", network_.alpha},
          {"beta", network_.beta},
          {"layers", layers},
          {"training", {{"epochs", training_.epochs}, {"training_mse", training_.training_mse}}}};
}

PaperMlpGroundModel PaperMlpGroundModel::from_parameters_json(const nlohmann::json& parameters,
                                                              const OmniModelDomain& domain) {
  const std::string where = "parameters";
  json_require_string(parameters, "activation", where, "sigmoid_sym");
  PaperMlpNetwork network;
  network.alpha = json_number(parameters, "alpha", where);
  network.beta = json_number(parameters, "beta", where);
  const nlohmann::json& layers = json_member(parameters, "layers", where);
  require(layers.is_array() && !layers.empty() && layers.size() <= 8, where + ".layers",
          "expected an array of 1 to 8 layers");
  Eigen::Index inputs = 2;
  for (std::size_t l = 0; l < layers.size(); ++l) {
    const std::string at = where + ".layers[" + std::to_string(l) + "]";
    const std::vector<double> bias = json_numbers(layers[l], "bias", at);
    require(!bias.empty() && (l + 1 < layers.size() || bias.size() == 1), at + ".bias",
            "expected one value per neuron and one output neuron");
    const nlohmann::json& rows = json_member(layers[l], "weights", at);
    require(rows.is_array() && rows.size() == bias.size(), at + ".weights",
            "expected one row per neuron");
    MlpLayer layer;
    layer.weights.resize(static_cast<Eigen::Index>(bias.size()), inputs);
    layer.bias = Eigen::Map<const Eigen::VectorXd>(bias.data(), layer.weights.rows());
    for (std::size_t o = 0; o < rows.size(); ++o) {
      const std::vector<double> row = json_number_array(
          rows[o], at + ".weights[" + std::to_string(o) + "]", static_cast<std::size_t>(inputs));
      layer.weights.row(static_cast<Eigen::Index>(o)) =
          Eigen::Map<const Eigen::RowVectorXd>(row.data(), inputs);
    }
    inputs = layer.weights.rows();
    network.layers.push_back(std::move(layer));
  }
  return {std::move(network), domain};
}

PaperMlpGroundModel fit_paper_mlp_model(std::span<const PolarSample> samples,
                                        const OmniImage& image, const PaperMlpFitOptions& options) {
  options.validate();
  image.validate();
  require(samples.size() >= kMinSamples, "samples",
          "paper-mlp needs at least " + std::to_string(kMinSamples) + " samples, got " +
              std::to_string(samples.size()));

  const int count = static_cast<int>(samples.size());
  cv::Mat inputs(count, 2, CV_32F);
  cv::Mat targets(count, 1, CV_32F);
  for (int i = 0; i < count; ++i) {  // Eq. 2 (as Table II), 3 and 4
    const PolarSample& s = samples[static_cast<std::size_t>(i)];
    inputs.at<float>(i, 0) = static_cast<float>(paper_normalised_direction(s.theta_deg));
    inputs.at<float>(i, 1) = static_cast<float>(paper_normalised_radius(s.radius_px));
    targets.at<float>(i, 0) = static_cast<float>(paper_normalised_distance(s.distance_cm));
  }

  std::vector<int> sizes{2};
  for (int l = 0; l < options.hidden_layers; ++l) sizes.push_back(options.hidden_neurons);
  sizes.push_back(1);
  const cv::Ptr<cv::ml::ANN_MLP> mlp = cv::ml::ANN_MLP::create();
  mlp->setLayerSizes(sizes);
  constexpr double kAlpha = 1.0, kBeta = 1.0;  // the logistic sigmoid, scaled to (-1, 1)
  mlp->setActivationFunction(cv::ml::ANN_MLP::SIGMOID_SYM, kAlpha, kBeta);
  if (options.use_rprop) {
    mlp->setTrainMethod(cv::ml::ANN_MLP::RPROP);
  } else {
    mlp->setTrainMethod(cv::ml::ANN_MLP::BACKPROP, 0.1, 0.1);  // OpenCV's default rates
  }
  const cv::Ptr<cv::ml::TrainData> data =
      cv::ml::TrainData::create(inputs, cv::ml::ROW_SAMPLE, targets);
  // Our own normalisation (Eq. 2-4) replaces OpenCV's input and output scaling.
  constexpr int kNoScaling = cv::ml::ANN_MLP::NO_INPUT_SCALE | cv::ml::ANN_MLP::NO_OUTPUT_SCALE;

  PaperMlpNetwork best;
  PaperMlpTraining training;
  training.training_mse = INFINITY;
  const int epochs_per_block = std::max(1, options.updates_per_block / count);
  int epochs = 0;
  int stale_blocks = 0;
  while (epochs < options.max_epochs && stale_blocks < options.patience_blocks) {
    const int block = std::min(epochs_per_block, options.max_epochs - epochs);
    // Exactly `block` epochs: OpenCV always adds an epsilon test on the change of the training
    // error, at least DBL_EPSILON, which this makes unreachable in practice.
    mlp->setTermCriteria(
        cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, block, 0.0));
    const int flags = epochs == 0 ? kNoScaling : kNoScaling | cv::ml::ANN_MLP::UPDATE_WEIGHTS;
    require(mlp->train(data, flags), "paper-mlp", "OpenCV's ANN_MLP training did not run");
    epochs += block;
    PaperMlpNetwork network = network_from_opencv(*mlp, sizes.size(), kAlpha, kBeta);
    const double mse = training_mse(network, inputs, targets);
    const bool improved = mse < (1.0 - options.min_improvement) * training.training_mse;
    stale_blocks = improved ? 0 : stale_blocks + 1;
    if (mse < training.training_mse) {
      best = std::move(network);
      training.training_mse = mse;
    }
  }
  training.epochs = epochs;
  check_same_as_opencv(network_from_opencv(*mlp, sizes.size(), kAlpha, kBeta), *mlp, inputs);
  return {std::move(best), {image, valid_radius_from_samples(samples)}, training};
}

}  // namespace ballsight
