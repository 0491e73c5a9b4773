#pragma once
// The omni calibration page's API (/api/v1/omni/..., docs/web-pages.md): frames (uploaded, a file
// of the server's folder, or the simulated omni robot's calibration frame) with a suggested image
// centre from the mirror's rim, the floor markers found in a frame, layout places for clicked
// points, samples CSV export and import, fits of any method run in the background, and their
// lookup tables (ballsight's format and the IRIS team's int16 px2cm). Every step is the library's
// (pipeline/omni_calibration.hpp), as the command line runs it. Nothing here writes to the
// server's disk, so no request needs the token.

#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <opencv2/core.hpp>
#include <string>

#include "ballsight/net/api_routes.hpp"

namespace ballsight {

struct OmniCalibrationOptions {
  /// Images offered by name (GET /api/v1/omni/files); empty: none.
  std::filesystem::path frames_dir;
  /// The simulated omni robot's calibration frame ({"simulated": true}); empty: none.
  std::function<cv::Mat()> simulated_frame;
  std::size_t max_frames = 8;  // the oldest is forgotten beyond
  std::size_t max_fits = 16;
  std::size_t max_image_pixels = 4096 * 4096;
};

class OmniCalibrationApi {
 public:
  explicit OmniCalibrationApi(OmniCalibrationOptions options = {});
  /// Waits for the fits still running.
  ~OmniCalibrationApi();
  OmniCalibrationApi(const OmniCalibrationApi&) = delete;
  OmniCalibrationApi& operator=(const OmniCalibrationApi&) = delete;

  /// Adds this API's route (/api/v1/omni/) to `routes`; the API must outlive their use. It
  /// runs long: its steps (a frame's markers found, a table built) take more than a moment.
  void register_routes(ApiRoutes& routes);
  /// Answers one request; never throws for anything a client sends. Fits run on a thread of
  /// their own: POST answers 202 at once, GET of the fit says when it is done.
  ApiResponse handle(const ApiRequest& request);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ballsight
