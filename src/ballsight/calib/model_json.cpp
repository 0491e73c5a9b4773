#include "ballsight/calib/model_json.hpp"

#include <nlohmann/json.hpp>

#include "ballsight/calib/omni_model_fit.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/core/json_fields.hpp"

namespace ballsight {

namespace {

constexpr std::string_view kFormat = "ballsight-omni-model";
constexpr int kVersion = 1;

OmniModelDomain domain_from_json(const nlohmann::json& document) {
  OmniModelDomain domain;
  const nlohmann::json& image = json_member(document, "image", "model");
  domain.image.width = json_int(image, "width", "image", 16, 16384);
  domain.image.height = json_int(image, "height", "image", 16, 16384);
  const std::vector<double> center = json_numbers(image, "center_px", "image", 2);
  domain.image.center_px = {center[0], center[1]};
  domain.image.validate();
  const std::vector<double> range = json_numbers(document, "valid_radius_px", "model", 2);
  require(range[0] >= 0.0 && range[0] < range[1], "model.valid_radius_px",
          "expected [min, max] with 0 <= min < max");
  domain.valid_radius = {range[0], range[1]};
  return domain;
}

}  // namespace

nlohmann::json omni_model_to_json(const OmniGroundModel& model) {
  const OmniModelDomain& domain = model.domain();
  return {{"format", kFormat},
          {"version", kVersion},
          {"method", model.name()},
          {"image",
           {{"width", domain.image.width},
            {"height", domain.image.height},
            {"center_px", {domain.image.center_px.x(), domain.image.center_px.y()}}}},
          {"valid_radius_px", {domain.valid_radius.min_px, domain.valid_radius.max_px}},
          {"parameters", model.parameters_json()}};
}

std::unique_ptr<OmniGroundModel> omni_model_from_json(const nlohmann::json& document,
                                                      const std::string& source) {
  try {
    json_require_string(document, "format", "model", std::string(kFormat));
    require(json_int(document, "version", "model", 0, 1 << 20) == kVersion, "model.version",
            "expected " + std::to_string(kVersion));
    const OmniMethod method =
        parse_omni_method(json_string(document, "method", "model"), "model.method");
    const OmniModelDomain domain = domain_from_json(document);
    const nlohmann::json& parameters = json_member(document, "parameters", "model");
    switch (method) {
      case OmniMethod::kPoly:
        return std::make_unique<PolynomialGroundModel>(
            PolynomialGroundModel::from_parameters_json(parameters, domain));
      case OmniMethod::kPaperMlp:
        return std::make_unique<PaperMlpGroundModel>(
            PaperMlpGroundModel::from_parameters_json(parameters, domain));
      case OmniMethod::kBallsight:
        return std::make_unique<BallsightGroundModel>(
            BallsightGroundModel::from_parameters_json(parameters, domain));
    }
    throw InputError("model.method: unknown");
  } catch (const InputError& e) {
    throw InputError(source + ": " + e.what());
  }
}

void save_omni_model(const std::filesystem::path& path, const OmniGroundModel& model) {
  write_file_atomic(path, omni_model_to_json(model).dump(2) + "\n");
}

std::unique_ptr<OmniGroundModel> load_omni_model(const std::filesystem::path& path) {
  return omni_model_from_json(read_json_document(path), path.string());
}

}  // namespace ballsight
