#pragma once
// The omni truth as JSON (nlohmann), the format `ballsight sim omni` writes next to each image.
// Every field, its unit and its axes are documented in docs/sim-omni.md.

#include <nlohmann/json.hpp>
#include <string>

#include "ballsight/sim/omni_truth.hpp"

namespace ballsight::sim {

inline constexpr const char* kOmniTruthFormat = "ballsight.sim.omni.truth";
inline constexpr int kOmniTruthVersion = 1;

nlohmann::ordered_json omni_truth_to_json(const OmniTruth& truth);

/// The document as text: indented objects, arrays of numbers on one line, a final newline.
std::string omni_truth_json_text(const OmniTruth& truth);

/// Parses a truth document; throws InputError naming `source` and the bad or missing key.
OmniTruth omni_truth_from_json(const nlohmann::ordered_json& document, const std::string& source);

}  // namespace ballsight::sim
