#pragma once
// The court calibration page's API (/api/v1/court-calibration/..., docs/web-pages.md): per camera
// a still (its last frame, kept while the user works on it), the reference balls found in it with
// their names and the pose fitted to them, corrected by hand (a ball placed where the user sees
// it, or marked absent), the residual of every ball; the camera's calibration file with that pose
// (downloaded, or written on the server: that needs the token); and a ball colour model learned
// from a few clicked ball pixels, with the balls it finds in the still. Every step is the
// library's, as `court calibrate`, `colours learn` and `detect balls` run it.

#include <cstddef>
#include <functional>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ballsight/camera/pinhole.hpp"
#include "ballsight/net/api_routes.hpp"
#include "ballsight/world/site.hpp"

namespace ballsight {

struct CourtCalibrationApiOptions {
  Site site;
  /// Every camera's intrinsics (from its calibration), in site order.
  std::vector<PinholeParams> intrinsics;
  /// Camera k's latest frame; nullopt while it has delivered none.
  std::function<std::optional<cv::Mat>(std::size_t camera)> latest_frame;
  /// PUT .../calibration writes the camera's calibration file (the site's); false: the service
  /// has no files (the simulated court), the page offers the file as a download only.
  bool write_files = false;
  /// After a calibration file was written: the running service takes the new pose (it throws
  /// InputError when it cannot). Empty: nothing.
  std::function<void()> on_saved;
  std::size_t max_stills = 16;  // the oldest is forgotten beyond
};

class CourtCalibrationApi {
 public:
  /// Throws InputError when the intrinsics are not one per site camera, or a site with cameras
  /// has no latest_frame.
  explicit CourtCalibrationApi(CourtCalibrationApiOptions options);
  ~CourtCalibrationApi();
  CourtCalibrationApi(const CourtCalibrationApi&) = delete;
  CourtCalibrationApi& operator=(const CourtCalibrationApi&) = delete;

  /// Adds this API's route (/api/v1/court-calibration/) to `routes`; the API must outlive their
  /// use. It runs long: its steps (a pose search, a colour model) take more than a moment.
  void register_routes(ApiRoutes& routes);
  /// Answers one request; never throws for anything a client sends.
  ApiResponse handle(const ApiRequest& request);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ballsight
