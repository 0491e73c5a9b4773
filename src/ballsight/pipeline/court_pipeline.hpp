#pragma once
// A court method end to end on one frame set: one image per camera -> detections per camera (in
// parallel, a thread per camera, as the tennis-ball-collecting-robot report's section 7.7 does
// with std::async; here the threads live as long as the pipeline) -> world model. Two methods
// behind one interface: the report's pipeline (the baseline) and ballsight's.

#include <memory>
#include <mutex>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ballsight/camera/field_camera.hpp"
#include "ballsight/core/pixel_detection.hpp"
#include "ballsight/detect/court_detector.hpp"
#include "ballsight/detect/court_foreground.hpp"
#include "ballsight/detect/seed_detector.hpp"
#include "ballsight/pipeline/frame_set.hpp"
#include "ballsight/world/court_world.hpp"
#include "ballsight/world/seed_world.hpp"
#include "ballsight/world/world_model.hpp"

namespace ballsight {

enum class CourtMethod { seed, ballsight };

/// "seed", "ballsight".
std::string court_method_name(CourtMethod method);

/// Per camera in camera order: its detections, or nullopt when its frame was missing or unusable.
using CameraDetectionLists = std::vector<std::optional<std::vector<PixelDetection>>>;

struct FrameSetResult {
  CameraDetectionLists detections;
  /// Per camera: why its frame was not used (empty when it was).
  std::vector<std::string> camera_errors;
  WorldModel world;
};

class CameraWorkers;

class CourtPipeline {
 public:
  virtual ~CourtPipeline();

  /// One frame per camera in camera order; an empty image is a missing frame. A frame that is
  /// not 8-bit BGR of its camera's calibrated size is not used, and camera_errors says why. The
  /// cameras are detected in parallel (a long-lived thread each: camera_workers.hpp), then fused;
  /// the world model carries the capture time of the frames it was made from.
  FrameSetResult process(const FrameSet& frames);
  /// The first half on its own (a camera node): camera `camera`'s detections in `frame`, which
  /// frame_problem() accepts. Calls for different cameras may run at once.
  virtual std::vector<PixelDetection> detect(std::size_t camera, const cv::Mat& frame) = 0;
  /// The second half on its own (a court node): the world model from one detection list per
  /// camera in camera order (nullopt: no usable frame of that camera).
  virtual WorldModel fuse(const CameraDetectionLists& detections) = 0;
  virtual CourtMethod method() const = 0;
  virtual const std::vector<FieldCamera>& cameras() const = 0;

 private:
  std::once_flag workers_once_;
  std::unique_ptr<CameraWorkers> workers_;  // started at the first frame set
};

struct SeedPipelineOptions {
  SeedDetectorOptions detector;
  SeedWorldOptions world;
};

struct BallsightPipelineOptions {
  CourtDetectorOptions detector;
  CourtWorldOptions world;
  /// Frame sets in sequence (the service): balls hidden by the robot's body and obstacles beside
  /// it are remembered (world/hidden_balls.hpp, world/hidden_obstacles.hpp). Off for independent
  /// scenes (`eval court`).
  bool remember_hidden_balls = false;
  /// Per camera in camera order, its view of the empty court: what differs from it is reported as
  /// obstacle views (detect/court_foreground.hpp) and put on the floor by the world model. Empty:
  /// no obstacles are looked for.
  std::vector<cv::Mat> empty_court;
  ForegroundOptions foreground;
};

std::unique_ptr<CourtPipeline> make_seed_pipeline(std::vector<FieldCamera> cameras,
                                                  const SeedPipelineOptions& options = {});
std::unique_ptr<CourtPipeline> make_ballsight_pipeline(
    std::vector<FieldCamera> cameras, const BallsightPipelineOptions& options = {});

/// Why `frame` cannot be used with `camera` ("" when it can): empty, not 8-bit BGR, or another
/// size than the camera's calibration.
std::string frame_problem(const cv::Mat& frame, const FieldCamera& camera);

}  // namespace ballsight
