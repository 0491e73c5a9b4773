#pragma once
// The three omni mapping methods behind one call: fit a model of `method` to polar samples.

#include <memory>
#include <span>
#include <string_view>

#include "ballsight/calib/ballsight_model.hpp"
#include "ballsight/calib/omni_ground_model.hpp"
#include "ballsight/calib/paper_mlp_model.hpp"
#include "ballsight/calib/polynomial_model.hpp"

namespace ballsight {

enum class OmniMethod { kPoly, kPaperMlp, kBallsight };

/// "poly", "paper-mlp", "ballsight".
std::string_view omni_method_name(OmniMethod method);
/// The method named `name`; throws InputError naming `where` and the choices otherwise.
OmniMethod parse_omni_method(std::string_view name, const std::string& where = "method");

struct OmniFitOptions {
  PolynomialFitOptions poly;
  PaperMlpFitOptions paper_mlp;
  BallsightFitOptions ballsight;
};

/// Fits `method` to the samples, whose polar coordinates are around `image.center_px`.
/// Throws InputError for bad options or too few samples for the method.
std::unique_ptr<OmniGroundModel> fit_omni_model(OmniMethod method,
                                                std::span<const PolarSample> samples,
                                                const OmniImage& image,
                                                const OmniFitOptions& options = {});

}  // namespace ballsight
