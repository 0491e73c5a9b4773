#pragma once
// A simulated omni data set on disk: omni_NNNN.png and omni_NNNN.json (truth) per frame of an
// omni scenario. What `ballsight sim omni` writes; documented in docs/sim-omni.md.

#include <filesystem>
#include <string>
#include <vector>

#include "ballsight/sim/omni_scenario.hpp"

namespace ballsight::sim {

/// Renders the scenario into `out_dir` (created if missing); returns the file names written, in
/// order. Same options, same bytes.
std::vector<std::string> write_omni_dataset(const OmniScenarioOptions& options,
                                            const std::filesystem::path& out_dir);

}  // namespace ballsight::sim
