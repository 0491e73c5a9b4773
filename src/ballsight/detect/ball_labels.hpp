#pragma once
// Labelled photos of tennis balls, and how a detector's balls are scored against the labels.
// A labelled source is a folder with `labels.csv` (`image,cx,cy,r`: pixels, the centre of the
// labeller's box and r = (box width + box height) / 4) and its photos under images/; a photo of
// images/ without a row holds no ball. A detection finds a label when the centre of its circle's
// visible part (the circle's box clipped to the image, as a labeller boxes a ball cut by the
// border) lies within the label's radius of the label's centre. Detections are taken best score
// first, each to the nearest free label; each label matches once, so a duplicate counts against
// precision.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ballsight/core/geometry.hpp"
#include "ballsight/detect/photo_balls.hpp"

namespace ballsight {

struct LabelledBall {
  Vec2 center_px = Vec2::Zero();  // pixel centres at integer coordinates
  double radius_px = 0.0;
};

struct LabelledImage {
  std::string file;  // name in the source's images/ folder
  std::vector<LabelledBall> balls;
};

struct LabelledSource {
  std::string name;  // the folder's name
  std::filesystem::path images_dir;
  std::vector<LabelledImage> images;  // in file name order
};

/// A row of a labels.csv.
struct LabelRow {
  std::string image;
  LabelledBall ball;
  int line = 0;  // 1-based, in the file
};
/// The rows of a labels.csv, in file order; throws InputError naming `where`:line of a malformed
/// row or header.
std::vector<LabelRow> parse_ball_labels(std::string_view csv, const std::string& where);
/// The source of `folder` (its labels.csv and images/). Throws InputError naming the file and line
/// of a malformed row, or a labelled image missing from images/.
LabelledSource read_labelled_source(const std::filesystem::path& folder);
/// Every folder with a labels.csv under `root`, in name order; none when `root` is absent.
std::vector<LabelledSource> read_labelled_sources(const std::filesystem::path& root);

/// The label of a labeller's box (pixel edges): its centre (as a pixel coordinate) and
/// (width + height) / 4.
LabelledBall label_of_box(const cv::Rect2d& box);

struct BallMatch {
  int labelled = 0;
  int detected = 0;
  int matched = 0;
  std::vector<double> center_error_px;     // per matched label
  std::vector<double> center_error_radii;  // per matched label: in the label's radius
  std::vector<double> label_radius_px;     // per label
  std::vector<bool> label_matched;         // per label
};

/// `balls` less those that lie on an ignored object (within its radius and kIgnoredMarginPx: a
/// simulated frame's reference balls, markers and balls too small or hidden to be labelled, on
/// which a detection is neither right nor wrong) and on no label (within its radius).
std::vector<PhotoBall> without_ignored(std::span<const PhotoBall> balls,
                                       std::span<const LabelledBall> labels,
                                       std::span<const LabelledBall> ignored);
inline constexpr double kIgnoredMarginPx = 2.0;

/// Matches `balls`, taken best score first, to `labels` in an image of `image_size`.
BallMatch match_balls_to_labels(std::span<const LabelledBall> labels,
                                std::span<const PhotoBall> balls, cv::Size image_size);

/// Adds `part`'s counts and centre errors to `total`.
void add_match(BallMatch& total, const BallMatch& part);
double recall(const BallMatch& match);
double precision(const BallMatch& match);
double f1_score(const BallMatch& match);

/// The labels of radius [min, max) px and how many of them were matched.
struct RadiusRecall {
  double min_radius_px = 0.0;
  double max_radius_px = 0.0;
  int labelled = 0;
  int matched = 0;
};
double recall(const RadiusRecall& range);

/// The labels in each radius range of `edges` (strictly ascending, else InputError; the last range
/// is open, and labels below the first edge are in no range).
std::vector<RadiusRecall> recall_by_radius(const BallMatch& match, std::span<const double> edges);

/// {"labelled", "detected", "matched", "recall", "precision", "f1", "median_center_error_px",
/// "median_center_error_radii"}.
nlohmann::json ball_match_json(const BallMatch& match);
/// [{"radius_px": [min, max or null], "labelled", "matched", "recall"}, ...]
nlohmann::json recall_by_radius_json(const std::vector<RadiusRecall>& ranges);

}  // namespace ballsight
