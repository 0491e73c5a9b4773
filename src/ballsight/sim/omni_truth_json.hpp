#pragma once
// The omni truth as JSON, the format `ballsight sim omni` writes next to each image. Every field,
// its unit and its axes are documented in docs/sim-omni.md.

#include <string>

#include "ballsight/sim/json_io.hpp"
#include "ballsight/sim/omni_truth.hpp"

namespace ballsight::sim {

inline constexpr const char* kOmniTruthFormat = "ballsight.sim.omni.truth";
inline constexpr int kOmniTruthVersion = 1;

Json omni_truth_to_json(const OmniTruth& truth);

/// The document as the file's text (json_text).
std::string omni_truth_json_text(const OmniTruth& truth);

/// Parses a truth document; throws InputError naming `source` and the bad or missing key.
OmniTruth omni_truth_from_json(const Json& document, const std::string& source);

}  // namespace ballsight::sim
