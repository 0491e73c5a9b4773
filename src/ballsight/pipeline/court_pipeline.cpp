#include "ballsight/pipeline/court_pipeline.hpp"

#include <functional>

#include "ballsight/core/error.hpp"
#include "ballsight/pipeline/camera_workers.hpp"
#include "ballsight/world/hidden_balls.hpp"
#include "ballsight/world/hidden_obstacles.hpp"

namespace ballsight {

std::string court_method_name(CourtMethod method) {
  return method == CourtMethod::seed ? "seed" : "ballsight";
}

std::string frame_problem(const cv::Mat& frame, const FieldCamera& camera) {
  if (frame.empty()) return "no frame";
  if (frame.type() != CV_8UC3) return "frame is not an 8-bit BGR image";
  if (frame.cols != camera.camera.width() || frame.rows != camera.camera.height())
    return "frame is " + std::to_string(frame.cols) + "x" + std::to_string(frame.rows) +
           " but the camera's calibration is for " + std::to_string(camera.camera.width()) + "x" +
           std::to_string(camera.camera.height());
  return "";
}

FrameSetResult CourtPipeline::process(const FrameSet& frames) {
  const std::vector<FieldCamera>& all = cameras();
  require(frames.cameras.size() == all.size(), "court pipeline",
          "expected " + std::to_string(all.size()) + " frames (one per camera), got " +
              std::to_string(frames.cameras.size()));
  FrameSetResult result;
  result.detections.resize(all.size());
  result.camera_errors.resize(all.size());
  std::vector<std::function<void()>> jobs(all.size());
  for (size_t c = 0; c < all.size(); ++c) {
    const CameraFrame& frame = frames.cameras[c];
    require(frame.camera == c, "court pipeline",
            "frame " + std::to_string(c) + " is camera " + std::to_string(frame.camera) +
                "'s: frames must be in camera order");
    result.camera_errors[c] = frame_problem(frame.image, all[c]);
    if (result.camera_errors[c].empty())
      jobs[c] = [this, &frame, &result, c] { result.detections[c] = detect(c, frame.image); };
  }
  std::call_once(workers_once_, [&] { workers_ = std::make_unique<CameraWorkers>(all.size()); });
  workers_->run(jobs);
  result.world = fuse(result.detections);
  std::vector<bool> used(all.size());
  for (size_t c = 0; c < all.size(); ++c) used[c] = result.camera_errors[c].empty();
  result.world.capture_time_ns = frames.capture_time_ns(used);
  return result;
}

CourtPipeline::~CourtPipeline() = default;

namespace {

class SeedPipeline final : public CourtPipeline {
 public:
  SeedPipeline(std::vector<FieldCamera> cameras, const SeedPipelineOptions& options)
      : cameras_(std::move(cameras)), options_(options) {
    options_.detector.validate();
    options_.world.validate();
  }

  std::vector<PixelDetection> detect(std::size_t, const cv::Mat& frame) override {
    return detect_seed(frame, options_.detector);
  }
  WorldModel fuse(const CameraDetectionLists& detections) override {
    return build_seed_world_model(cameras_, detections, options_.world);
  }
  CourtMethod method() const override { return CourtMethod::seed; }
  const std::vector<FieldCamera>& cameras() const override { return cameras_; }

 private:
  std::vector<FieldCamera> cameras_;
  SeedPipelineOptions options_;
};

class BallsightPipeline final : public CourtPipeline {
 public:
  BallsightPipeline(std::vector<FieldCamera> cameras, const BallsightPipelineOptions& options)
      : cameras_(std::move(cameras)), options_(options) {
    options_.world.validate();
    for (const FieldCamera& camera : cameras_) detectors_.emplace_back(camera, options_.detector);
    require(options_.empty_court.empty() || options_.empty_court.size() == cameras_.size(),
            "empty court views",
            "must be one per camera (" + std::to_string(cameras_.size()) + "), got " +
                std::to_string(options_.empty_court.size()));
    for (std::size_t c = 0; c < options_.empty_court.size(); ++c) {
      require(frame_problem(options_.empty_court[c], cameras_[c]).empty(),
              "empty court view " + std::to_string(c),
              frame_problem(options_.empty_court[c], cameras_[c]));
      foregrounds_.emplace_back(options_.empty_court[c], options_.foreground);
    }
  }

  std::vector<PixelDetection> detect(std::size_t camera, const cv::Mat& frame) override {
    std::vector<PixelDetection> found = detectors_[camera].detect(frame);
    if (!foregrounds_.empty()) {
      std::vector<PixelDetection> views = foregrounds_[camera].detect(frame);
      found.insert(found.end(), std::make_move_iterator(views.begin()),
                   std::make_move_iterator(views.end()));
    }
    return found;
  }
  WorldModel fuse(const CameraDetectionLists& detections) override {
    WorldModel world = build_world_model(cameras_, detections, options_.world);
    if (options_.remember_hidden_balls) {
      hidden_.apply(world);
      hidden_obstacles_.apply(world);
    }
    return world;
  }
  CourtMethod method() const override { return CourtMethod::ballsight; }
  const std::vector<FieldCamera>& cameras() const override { return cameras_; }

 private:
  std::vector<FieldCamera> cameras_;
  BallsightPipelineOptions options_;
  std::vector<CourtDetector> detectors_;      // one per camera: each task uses its own
  std::vector<CourtForeground> foregrounds_;  // one per camera, or none
  HiddenBallMemory hidden_;
  HiddenObstacleMemory hidden_obstacles_;
};

}  // namespace

std::unique_ptr<CourtPipeline> make_seed_pipeline(std::vector<FieldCamera> cameras,
                                                  const SeedPipelineOptions& options) {
  return std::make_unique<SeedPipeline>(std::move(cameras), options);
}

std::unique_ptr<CourtPipeline> make_ballsight_pipeline(std::vector<FieldCamera> cameras,
                                                       const BallsightPipelineOptions& options) {
  return std::make_unique<BallsightPipeline>(std::move(cameras), options);
}

}  // namespace ballsight
