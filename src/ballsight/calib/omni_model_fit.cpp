#include "ballsight/calib/omni_model_fit.hpp"

#include <array>
#include <string>

#include "ballsight/core/error.hpp"

namespace ballsight {

namespace {

constexpr std::array<std::pair<OmniMethod, std::string_view>, 3> kMethods = {{
    {OmniMethod::kPoly, "poly"},
    {OmniMethod::kPaperMlp, "paper-mlp"},
    {OmniMethod::kBallsight, "ballsight"},
}};

}  // namespace

std::string_view omni_method_name(OmniMethod method) {
  for (const auto& [m, name] : kMethods) {
    if (m == method) return name;
  }
  return "unknown";
}

OmniMethod parse_omni_method(std::string_view name, const std::string& where) {
  for (const auto& [method, n] : kMethods) {
    if (n == name) return method;
  }
  throw InputError(where + ": unknown method '" + std::string(name) +
                   "'; expected poly, paper-mlp or ballsight");
}

std::unique_ptr<OmniGroundModel> fit_omni_model(OmniMethod method,
                                                std::span<const PolarSample> samples,
                                                const OmniImage& image,
                                                const OmniFitOptions& options) {
  switch (method) {
    case OmniMethod::kPoly:
      return std::make_unique<PolynomialGroundModel>(
          fit_polynomial_model(samples, image, options.poly));
    case OmniMethod::kPaperMlp:
      return std::make_unique<PaperMlpGroundModel>(
          fit_paper_mlp_model(samples, image, options.paper_mlp));
    case OmniMethod::kBallsight:
      return std::make_unique<BallsightGroundModel>(
          fit_ballsight_model(samples, image, options.ballsight));
  }
  throw InputError("method: unknown");
}

}  // namespace ballsight
