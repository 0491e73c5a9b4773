#include "ballsight/pipeline/court_pipeline.hpp"

#include <future>

#include "ballsight/core/error.hpp"
#include "ballsight/world/hidden_balls.hpp"

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

namespace {

// Runs `detect(camera, frame)` for every usable frame, one std::async task per camera.
template <typename Detect>
FrameSetResult detect_all(const std::vector<cv::Mat>& frames,
                          const std::vector<FieldCamera>& cameras, Detect&& detect) {
  require(frames.size() == cameras.size(), "court pipeline",
          "expected " + std::to_string(cameras.size()) + " frames (one per camera), got " +
              std::to_string(frames.size()));
  FrameSetResult result;
  result.detections.resize(cameras.size());
  result.camera_errors.resize(cameras.size());
  std::vector<std::future<std::vector<PixelDetection>>> tasks(cameras.size());
  for (size_t c = 0; c < cameras.size(); ++c) {
    result.camera_errors[c] = frame_problem(frames[c], cameras[c]);
    if (result.camera_errors[c].empty())
      tasks[c] =
          std::async(std::launch::async, [&detect, &frames, c] { return detect(c, frames[c]); });
  }
  for (size_t c = 0; c < cameras.size(); ++c)
    if (tasks[c].valid()) result.detections[c] = tasks[c].get();
  return result;
}

class SeedPipeline final : public CourtPipeline {
 public:
  SeedPipeline(std::vector<FieldCamera> cameras, const SeedPipelineOptions& options)
      : cameras_(std::move(cameras)), options_(options) {
    options_.detector.validate();
    options_.world.validate();
  }

  FrameSetResult process(const std::vector<cv::Mat>& frames) override {
    FrameSetResult result = detect_all(frames, cameras_, [this](size_t, const cv::Mat& frame) {
      return detect_seed(frame, options_.detector);
    });
    result.world = build_seed_world_model(cameras_, result.detections, options_.world);
    return result;
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
  }

  FrameSetResult process(const std::vector<cv::Mat>& frames) override {
    FrameSetResult result = detect_all(frames, cameras_, [this](size_t c, const cv::Mat& frame) {
      return detectors_[c].detect(frame);
    });
    result.world = build_world_model(cameras_, result.detections, options_.world);
    if (options_.remember_hidden_balls) hidden_.apply(result.world);
    return result;
  }
  CourtMethod method() const override { return CourtMethod::ballsight; }
  const std::vector<FieldCamera>& cameras() const override { return cameras_; }

 private:
  std::vector<FieldCamera> cameras_;
  BallsightPipelineOptions options_;
  std::vector<CourtDetector> detectors_;  // one per camera: each task uses its own
  HiddenBallMemory hidden_;
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
