#pragma once
// Ball detectors on real labelled photos of other people (../shared/data/real/tennis): every set
// folder with a `balls.csv` (file, box x_min, y_min, width, height; empty box fields for a photo
// without balls) and its photos under images/. A detection counts when its centre lies inside a
// labelled box, each box matching once (detections taken best score first, each to the nearest
// free box holding it); the centre error is measured between the box and the detection's circle
// clipped to the image like the label, relative to the ball's radius (half the box's longer side).

#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <span>
#include <string>
#include <vector>

#include "ballsight/detect/ball_colours.hpp"
#include "ballsight/detect/photo_balls.hpp"

namespace ballsight {

struct LabelledPhoto {
  std::string file;  // name in the set's images/ folder
  std::vector<cv::Rect> boxes;
};

struct LabelledPhotoSet {
  std::string name;
  std::filesystem::path images_dir;
  std::vector<LabelledPhoto> photos;
};

/// The sets under `data_dir`/real/tennis; throws InputError naming the file and line of a
/// malformed label.
std::vector<LabelledPhotoSet> load_labelled_photo_sets(const std::filesystem::path& data_dir);

struct BoxMatch {
  int labelled = 0;
  int detected = 0;
  int matched = 0;
  std::vector<double> center_error_ratio;  // per matched box: centre error / ball radius
  std::vector<double> box_radius_px;       // per labelled box: half its longer side
  std::vector<bool> box_matched;           // per labelled box
};

/// The boxes of radius [min, max) px and how many of them were matched.
struct RadiusRecall {
  double min_radius_px = 0.0;
  double max_radius_px = 0.0;
  int labelled = 0;
  int matched = 0;
};

/// The boxes in each radius range of `edges` (strictly ascending, else InputError; the last range
/// is open, and boxes below the first edge are in no range).
std::vector<RadiusRecall> recall_by_radius(const BoxMatch& match, std::span<const double> edges);

/// Matches `balls` (best first) to `boxes` in an image of `image_size`.
BoxMatch match_balls_to_boxes(const std::vector<cv::Rect>& boxes,
                              const std::vector<PhotoBall>& balls, cv::Size image_size);

struct PhotoResult {
  std::string set;
  std::string file;
  BoxMatch match;
  double milliseconds = 0.0;  // median of the timing runs
};

struct TennisMethodResult {
  std::string method;  // "ballsight", "report-hsv"
  std::vector<PhotoResult> photos;
  BoxMatch total;
};

struct TennisRealOptions {
  std::filesystem::path data_dir = "../shared/data";
  BallColours colours = default_ball_colours();  // ballsight's colour model
  int timing_runs = 5;                           // per photo and method
};

struct TennisRealResult {
  std::vector<TennisMethodResult> methods;  // ballsight, then the report's HSV detector
};

/// Runs ballsight's detector and the tennis report's (HSV threshold, median filter, contours'
/// centres of mass, radius from the contour's area) on every labelled photo. Throws InputError
/// when `data_dir` holds no labelled set.
TennisRealResult run_tennis_real(const TennisRealOptions& options);

double recall(const BoxMatch& match);
double recall(const RadiusRecall& range);
double precision(const BoxMatch& match);
/// Adds `part`'s counts and centre errors to `total`.
void add_match(BoxMatch& total, const BoxMatch& part);
/// {"labelled", "detected", "matched", "recall", "precision", "median_center_error_ratio"}.
/// (recall_by_radius_json gives the boxes' recall by size.)
nlohmann::json box_match_json(const BoxMatch& match);
/// [{"radius_px": [min, max or null], "labelled", "matched", "recall"}, ...]
nlohmann::json recall_by_radius_json(const std::vector<RadiusRecall>& ranges);

/// The tennis report's detector (HSV threshold, median filter, contours' centres of mass, radius
/// from the contour's area), its detections with score 1.
std::vector<PhotoBall> report_hsv_balls(const cv::Mat& bgr);

nlohmann::json tennis_real_json(const TennisRealResult& result);
std::string tennis_real_table(const TennisRealResult& result);

}  // namespace ballsight
