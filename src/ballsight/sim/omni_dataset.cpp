#include "ballsight/sim/omni_dataset.hpp"

#include <cstdio>

#include "ballsight/sim/dataset_writer.hpp"
#include "ballsight/sim/omni_renderer.hpp"
#include "ballsight/sim/omni_truth_json.hpp"

namespace ballsight::sim {

std::vector<std::string> write_omni_dataset(const OmniScenarioOptions& options,
                                            const std::filesystem::path& out_dir) {
  const OmniScenario scenario = make_omni_scenario(options);
  DatasetWriter writer(out_dir);
  const OmniRenderer renderer(scenario.rig);
  for (std::size_t i = 0; i < scenario.scenes.size(); ++i) {
    const OmniFrame frame = renderer.render(scenario.scenes[i]);
    char stem[32];
    std::snprintf(stem, sizeof stem, "omni_%04zu", i);
    writer.png(std::string(stem) + ".png", frame.bgr);
    writer.json(std::string(stem) + ".json", omni_truth_to_json(frame.truth));
  }
  return std::move(writer).written();
}

cv::Mat render_calibration_frame(OmniScenarioOptions options) {
  options.frames = 1;
  options.calibration_frame = true;
  const OmniScenario scenario = make_omni_scenario(options);
  return render_omni_scene(scenario.scenes.front()).bgr;
}

}  // namespace ballsight::sim
