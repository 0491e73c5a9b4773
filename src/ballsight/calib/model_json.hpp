#pragma once
// A fitted omni model as a small JSON document: format and version, method, image (size and
// centre), valid radius range and the method's parameters. The lookup-table builder reads it.

#include <filesystem>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "ballsight/calib/omni_ground_model.hpp"

namespace ballsight {

nlohmann::json omni_model_to_json(const OmniGroundModel& model);
/// Throws InputError naming `source` and the offending field.
std::unique_ptr<OmniGroundModel> omni_model_from_json(const nlohmann::json& document,
                                                      const std::string& source);

/// Writes the model atomically.
void save_omni_model(const std::filesystem::path& path, const OmniGroundModel& model);
/// Reads a model file; errors name the file and the field.
std::unique_ptr<OmniGroundModel> load_omni_model(const std::filesystem::path& path);

}  // namespace ballsight
