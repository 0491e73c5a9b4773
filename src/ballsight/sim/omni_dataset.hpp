#pragma once
// A simulated omni data set on disk: omni_NNNN.png and omni_NNNN.json (truth) per frame of an
// omni scenario. What `ballsight sim omni` writes; documented in docs/sim-omni.md.

#include <filesystem>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "ballsight/sim/omni_scenario.hpp"

namespace ballsight::sim {

/// Renders the scenario into `out_dir` (created if missing); returns the file names written, in
/// order. Same options, same bytes.
std::vector<std::string> write_omni_dataset(const OmniScenarioOptions& options,
                                            const std::filesystem::path& out_dir);

/// Frame 0 of the scenario with its calibration frame: the markers around the robot, as
/// `ballsight sim omni` writes it to omni_0000.png.
cv::Mat render_calibration_frame(OmniScenarioOptions options);

}  // namespace ballsight::sim
