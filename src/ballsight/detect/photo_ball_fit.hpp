#pragma once
// Fitting the camera-free ball detector's settings to labelled photos: a few numbers of its
// colour model, of its contrast split and its score threshold, each searched over a fixed grid in
// turn (coordinate ascent, `rounds` passes), keeping a value only when it raises the mean over the
// sources of the F1 score (each source weighs the same, however many balls it has). Deterministic:
// the same photos and start give the same settings. Saved as JSON: {"format":
// "ballsight-photo-ball-detector", "version": 1, "colours": <ball colours, ball_colours.hpp>,
// "min_score": 0-1, "split": {"min_contrast", "max_share"} (ContrastSplit), "fitted_on": [source
// names], "mean_f1": the objective reached}.

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <span>
#include <string>
#include <vector>

#include "ballsight/detect/ball_labels.hpp"
#include "ballsight/detect/photo_balls.hpp"

namespace ballsight {

/// One source's photos, decoded.
struct LabelledPhotos {
  std::string source;
  std::vector<std::string> files;                 // per image: its name in images/
  std::vector<cv::Mat> images;                    // 8-bit BGR
  std::vector<std::vector<LabelledBall>> labels;  // per image
  /// Per image (or none): objects a detection on which is neither right nor wrong
  /// (without_ignored).
  std::vector<std::vector<LabelledBall>> ignored;

  /// The ignored objects of photo k (none when the source has none).
  std::span<const LabelledBall> ignored_in(std::size_t k) const {
    return k < ignored.size() ? std::span<const LabelledBall>(ignored[k])
                              : std::span<const LabelledBall>();
  }
};

/// Decodes every image of `source`; throws InputError naming an unreadable one.
LabelledPhotos read_labelled_photos(const LabelledSource& source);

/// The labelled sources under a folder (read_labelled_sources), decoded, those named apart.
struct PhotoSources {
  std::vector<LabelledPhotos> named;   // in the folder's order
  std::vector<LabelledPhotos> others;  // the rest
};
/// Throws InputError, where `option`, naming a name that is no source under `root`.
PhotoSources read_photo_sources(const std::filesystem::path& root,
                                std::span<const std::string> names, const std::string& option);

/// A source's match when `detector` looks at every photo of it.
BallMatch score_photos(PhotoBallDetector& detector, const LabelledPhotos& photos);
/// A source's match for the balls `balls_of(k)` in photo k.
BallMatch score_photos(const LabelledPhotos& photos,
                       const std::function<std::vector<PhotoBall>(std::size_t)>& balls_of);

struct PhotoBallFit {
  PhotoBallOptions options;
  std::vector<std::string> fitted_on;
  double mean_f1 = 0.0;
  int evaluations = 0;  // detector runs over all the photos
};

struct PhotoBallFitOptions {
  /// The search's first point (by default the hand-set PhotoBallOptions: default_ball_colours(),
  /// a score threshold of 0.35, the contrast split's 40 / 0.3); what it does not fit stays.
  PhotoBallOptions start;
  int rounds = 2;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// The settings that score best on `sources` (none: InputError).
PhotoBallFit fit_photo_ball_detector(std::span<const LabelledPhotos> sources,
                                     const PhotoBallFitOptions& options);

/// The detector as shipped: the settings `ballsight detect fit` wrote on every real labelled
/// source (detect/shipped_photo_ball_detector.json, which names the command), compiled in.
PhotoBallOptions shipped_photo_ball_options();

nlohmann::json photo_ball_fit_json(const PhotoBallFit& fit);
/// The detector settings of a fit's JSON; throws InputError naming `where` and the field.
PhotoBallOptions photo_ball_options_from_json(const nlohmann::json& json, const std::string& where);
/// Reads the settings a fit wrote; errors name the file and the field.
PhotoBallOptions read_photo_ball_options(const std::string& path);

}  // namespace ballsight
