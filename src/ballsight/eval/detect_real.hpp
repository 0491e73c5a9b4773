#pragma once
// `eval detect-real`: what a user on a court nobody here has seen gets from the camera-free ball
// detector. The real labelled sources (../shared/data/real/tennis, detect/ball_labels.hpp) are
// scored one by one: with the detector fitted without that source (leave one source out), with
// the detector as shipped, and with the tennis report's HSV detector as the baseline. Each
// missed label is given the first cause it shows (MissCause).

#include <array>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ballsight/detect/ball_labels.hpp"
#include "ballsight/detect/photo_ball_fit.hpp"
#include "ballsight/detect/photo_balls.hpp"

namespace ballsight {

/// Why a label was missed, the first that holds, in this order: its disc (of the label's radius)
/// comes within a pixel of the image border; its radius is below 4 px; another label's disc
/// touches or overlaps its own; less than half of its inner disc (0.7 of its radius) is of the
/// shipped colour model's growth colours; none of these.
enum class MissCause { border, small, touching, off_colour, other };
inline constexpr std::size_t kMissCauses = 5;
std::string_view miss_cause_name(MissCause cause);

/// The cause of missing `labels[k]` in `bgr`; `growth` classifies the inner disc's pixels.
MissCause miss_cause(const cv::Mat& bgr, std::span<const LabelledBall> labels, std::size_t k,
                     const ColorClassTable& growth);

struct SourceScore {
  std::string source;
  BallMatch match;
  std::array<int, kMissCauses> misses{};  // by MissCause
  double median_milliseconds = 0.0;       // per image
  nlohmann::json fit;                     // leave one source out: the settings fitted without it
};

struct DetectRealMethod {
  std::string method;  // "leave-one-source-out", "shipped", "report-hsv"
  std::vector<SourceScore> sources;
};

struct DetectRealResult {
  std::vector<DetectRealMethod> methods;
};

/// "verified": the shipped detector with the candidates a learned verifier (--verifier) takes
/// for balls, its threshold fitted leave one source out (detect/ball_verifier.hpp).
inline constexpr std::array<const char*, 4> kDetectRealMethods{"leave-one-source-out", "shipped",
                                                               "report-hsv", "verified"};

/// The simulator's scenes the shipped settings were fitted on (their JSON names the command).
inline constexpr int kShippedSimScenes = 4;

struct DetectRealOptions {
  std::filesystem::path data_dir = "../shared/data";
  PhotoBallOptions shipped = shipped_photo_ball_options();  // the detector as shipped
  PhotoBallFitOptions fit;  // how each source's leave-one-out settings are fitted
  /// Scenes of the simulator fitted on beside the other real sources (simulated_fitting_photos;
  /// as the shipped settings were: `detect fit --sim-scenes`); 0: none.
  int sim_scenes = kShippedSimScenes;
  /// Which of kDetectRealMethods to run, in that order whatever the order here.
  std::vector<std::string> methods{kDetectRealMethods.begin(), kDetectRealMethods.begin() + 3};
  /// The verifier's ONNX model (scripts/train_ball_verifier.py), which "verified" needs.
  std::filesystem::path verifier;
  /// Draws every image's labels (green) and each method's detections (magenta) into this folder
  /// as <method>/<source>/<image>.png; nothing when empty.
  std::filesystem::path draw_dir;
};

/// Scores the methods on every source under data_dir/real/tennis, the sources one by one (with
/// a single source there is nothing to leave it out of: no leave-one-source-out figure); throws
/// InputError when there is none, or when a method is none of kDetectRealMethods.
DetectRealResult run_detect_real(const DetectRealOptions& options);

nlohmann::json detect_real_json(const DetectRealResult& result);
std::string detect_real_table(const DetectRealResult& result);

/// The tennis report's detector (HSV threshold, median filter, contours' centres of mass, radius
/// from the contour's area), its detections with score 1.
std::vector<PhotoBall> report_hsv_balls(const cv::Mat& bgr);

}  // namespace ballsight
