#include "ballsight/eval/tennis_real.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>

#include "ballsight/camera/image_file.hpp"
#include "ballsight/core/csv_fields.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/core/statistics.hpp"
#include "ballsight/core/text_format.hpp"
#include "ballsight/detect/seed_detector.hpp"

namespace ballsight {

namespace fs = std::filesystem;

namespace {

constexpr const char* kHeader = "file,x_min,y_min,width,height";

LabelledPhotoSet read_labels(const fs::path& csv) {
  LabelledPhotoSet set;
  set.name = csv.parent_path().filename().string();
  set.images_dir = csv.parent_path() / "images";
  std::istringstream text(read_file(csv));
  std::string line;
  std::getline(text, line);
  require(line.starts_with(kHeader), csv.string() + ":1",
          std::string("expected the header ") + kHeader + ",...");
  std::map<std::string, std::size_t> index;
  for (int number = 2; std::getline(text, line); ++number) {
    if (trim_blanks(line).empty()) continue;
    const std::string where = csv.string() + ":" + std::to_string(number);
    const std::vector<CsvField> fields = split_csv_fields(line);
    require(fields.size() >= 5 && !fields[0].text.empty(), where,
            "expected a file name and four box fields");
    const std::string file(fields[0].text);
    const auto [it, added] = index.emplace(file, set.photos.size());
    if (added) set.photos.push_back({file, {}});
    if (fields[1].text.empty() && fields[2].text.empty() && fields[3].text.empty() &&
        fields[4].text.empty())
      continue;  // a photo without balls
    double v[4];
    for (std::size_t k = 0; k < 4; ++k) v[k] = csv_number(fields[k + 1], where);
    require(v[2] >= 1.0 && v[3] >= 1.0, where, "expected a box of positive size");
    set.photos[it->second].boxes.emplace_back(static_cast<int>(v[0]), static_cast<int>(v[1]),
                                              static_cast<int>(v[2]), static_cast<int>(v[3]));
  }
  require(!set.photos.empty(), csv.string(), "holds no photo");
  return set;
}

Vec2 box_center(const cv::Rect2d& box) {
  return Vec2(box.x + 0.5 * box.width, box.y + 0.5 * box.height);
}

// The box a labeller draws around a ball: pixel edges from centre +- radius (pixel centres at
// integers), clipped to the image.
cv::Rect2d clipped_box(const PhotoBall& ball, cv::Size image_size) {
  const double x0 = std::max(0.0, ball.center_px.x() + 0.5 - ball.radius_px);
  const double y0 = std::max(0.0, ball.center_px.y() + 0.5 - ball.radius_px);
  const double x1 = std::min<double>(image_size.width, ball.center_px.x() + 0.5 + ball.radius_px);
  const double y1 = std::min<double>(image_size.height, ball.center_px.y() + 0.5 + ball.radius_px);
  return {x0, y0, std::max(0.0, x1 - x0), std::max(0.0, y1 - y0)};
}

using Detector = std::function<std::vector<PhotoBall>(const cv::Mat&)>;

TennisMethodResult run_method(const std::string& name, const Detector& detect,
                              const std::vector<LabelledPhotoSet>& sets, int timing_runs) {
  TennisMethodResult result{name, {}, {}};
  for (const LabelledPhotoSet& set : sets) {
    for (const LabelledPhoto& photo : set.photos) {
      const cv::Mat image = read_image_bgr(set.images_dir / photo.file);
      std::vector<double> ms;
      std::vector<PhotoBall> balls;
      for (int run = 0; run < timing_runs; ++run) {
        const auto start = std::chrono::steady_clock::now();
        balls = detect(image);
        ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count());
      }
      PhotoResult r{set.name, photo.file, match_balls_to_boxes(photo.boxes, balls, image.size()),
                    median(ms)};
      add_match(result.total, r.match);
      result.photos.push_back(std::move(r));
    }
  }
  return result;
}

double median_or_zero(const std::vector<double>& values) {
  return values.empty() ? 0.0 : median(values);
}

}  // namespace

std::vector<LabelledPhotoSet> load_labelled_photo_sets(const fs::path& data_dir) {
  std::vector<LabelledPhotoSet> sets;
  const fs::path root = data_dir / "real" / "tennis";
  std::error_code error;
  if (!fs::is_directory(root, error)) return sets;
  std::vector<fs::path> folders;
  for (const fs::directory_entry& entry : fs::directory_iterator(root))
    if (entry.is_directory() && fs::exists(entry.path() / "balls.csv")) folders.push_back(entry);
  std::sort(folders.begin(), folders.end());
  for (const fs::path& folder : folders) sets.push_back(read_labels(folder / "balls.csv"));
  return sets;
}

BoxMatch match_balls_to_boxes(const std::vector<cv::Rect>& boxes,
                              const std::vector<PhotoBall>& balls, cv::Size image_size) {
  BoxMatch match;
  match.labelled = static_cast<int>(boxes.size());
  match.detected = static_cast<int>(balls.size());
  std::vector<bool> taken(boxes.size(), false);
  for (const cv::Rect& box : boxes)
    match.box_radius_px.push_back(0.5 * std::max(box.width, box.height));
  for (const PhotoBall& ball : balls) {
    std::size_t best = boxes.size();
    double best_distance = 0.0;
    // The centre of what is visible, as the label's: a ball cut by the border has its centre
    // outside the image, its label box only the visible part. Box edges are pixel edges.
    const Vec2 c = box_center(clipped_box(ball, image_size));
    for (std::size_t k = 0; k < boxes.size(); ++k) {
      const cv::Rect2d box(boxes[k]);
      if (taken[k] || c.x() < box.x || c.y() < box.y || c.x() >= box.x + box.width ||
          c.y() >= box.y + box.height)
        continue;
      const double distance = (box_center(box) - c).norm();
      if (best == boxes.size() || distance < best_distance) best = k, best_distance = distance;
    }
    if (best == boxes.size()) continue;
    taken[best] = true;
    ++match.matched;
    const cv::Rect2d box(boxes[best]);
    match.center_error_ratio.push_back((c - box_center(box)).norm() / match.box_radius_px[best]);
  }
  match.box_matched = taken;
  return match;
}

void add_match(BoxMatch& total, const BoxMatch& part) {
  total.labelled += part.labelled;
  total.detected += part.detected;
  total.matched += part.matched;
  total.center_error_ratio.insert(total.center_error_ratio.end(), part.center_error_ratio.begin(),
                                  part.center_error_ratio.end());
  total.box_radius_px.insert(total.box_radius_px.end(), part.box_radius_px.begin(),
                             part.box_radius_px.end());
  total.box_matched.insert(total.box_matched.end(), part.box_matched.begin(),
                           part.box_matched.end());
}

std::vector<RadiusRecall> recall_by_radius(const BoxMatch& match, std::span<const double> edges) {
  require(std::adjacent_find(edges.begin(), edges.end(), std::greater_equal<>()) == edges.end(),
          "radius ranges", "edges must be strictly ascending");
  std::vector<RadiusRecall> ranges;
  for (std::size_t k = 0; k < edges.size(); ++k)
    ranges.push_back({edges[k],
                      k + 1 < edges.size() ? edges[k + 1] : std::numeric_limits<double>::infinity(),
                      0, 0});
  for (std::size_t b = 0; b < match.box_radius_px.size(); ++b)
    for (RadiusRecall& range : ranges)
      if (match.box_radius_px[b] >= range.min_radius_px &&
          match.box_radius_px[b] < range.max_radius_px) {
        ++range.labelled;
        range.matched += match.box_matched[b];
      }
  return ranges;
}

std::vector<PhotoBall> report_hsv_balls(const cv::Mat& bgr) {
  const SeedDetectorOptions options;
  std::vector<PhotoBall> balls;
  for (const PixelDetection& d :
       detect_seed_colour(bgr, options.ball, options.median_kernel_px, ObjectClass::ball))
    balls.push_back({d.center_px, d.radius_px, 1.0});
  return balls;
}

double recall(const BoxMatch& match) {
  return match.labelled > 0 ? static_cast<double>(match.matched) / match.labelled : 1.0;
}

double recall(const RadiusRecall& range) {
  return range.labelled > 0 ? static_cast<double>(range.matched) / range.labelled : 1.0;
}

double precision(const BoxMatch& match) {
  return match.detected > 0 ? static_cast<double>(match.matched) / match.detected : 1.0;
}

TennisRealResult run_tennis_real(const TennisRealOptions& options) {
  require(options.timing_runs >= 1, "timing runs", "must be at least 1");
  const std::vector<LabelledPhotoSet> sets = load_labelled_photo_sets(options.data_dir);
  require(!sets.empty(), options.data_dir.string(),
          "holds no labelled photo set (real/tennis/*/balls.csv)");
  PhotoBallOptions ballsight_options;
  ballsight_options.colours = options.colours;
  PhotoBallDetector detector(ballsight_options);
  TennisRealResult result;
  result.methods.push_back(run_method(
      "ballsight", [&detector](const cv::Mat& bgr) { return detector.detect(bgr); }, sets,
      options.timing_runs));
  result.methods.push_back(run_method("report-hsv", report_hsv_balls, sets, options.timing_runs));
  return result;
}

nlohmann::json box_match_json(const BoxMatch& match) {
  return {{"labelled", match.labelled},
          {"detected", match.detected},
          {"matched", match.matched},
          {"recall", recall(match)},
          {"precision", precision(match)},
          {"median_center_error_ratio", median_or_zero(match.center_error_ratio)}};
}

nlohmann::json recall_by_radius_json(const std::vector<RadiusRecall>& ranges) {
  nlohmann::json list = nlohmann::json::array();
  for (const RadiusRecall& range : ranges) {
    const nlohmann::json upper = std::isfinite(range.max_radius_px)
                                     ? nlohmann::json(range.max_radius_px)
                                     : nlohmann::json(nullptr);
    list.push_back(
        {{"radius_px", {range.min_radius_px, upper}},
         {"labelled", range.labelled},
         {"matched", range.matched},
         {"recall", range.labelled > 0 ? nlohmann::json(recall(range)) : nlohmann::json()}});
  }
  return list;
}

nlohmann::json tennis_real_json(const TennisRealResult& result) {
  nlohmann::json methods = nlohmann::json::array();
  for (const TennisMethodResult& method : result.methods) {
    nlohmann::json photos = nlohmann::json::array();
    std::vector<double> ms;
    for (const PhotoResult& photo : method.photos) {
      nlohmann::json p = box_match_json(photo.match);
      p["set"] = photo.set;
      p["file"] = photo.file;
      p["milliseconds"] = photo.milliseconds;
      photos.push_back(p);
      ms.push_back(photo.milliseconds);
    }
    nlohmann::json m = box_match_json(method.total);
    m["method"] = method.method;
    m["median_milliseconds"] = median_or_zero(ms);
    m["photos"] = photos;
    methods.push_back(m);
  }
  return {{"methods", methods}};
}

std::string tennis_real_table(const TennisRealResult& result) {
  std::ostringstream out;
  out << std::left << std::setw(11) << "method" << std::setw(42) << "set/photo" << std::right
      << std::setw(6) << "boxes" << std::setw(6) << "found" << std::setw(6) << "match"
      << std::setw(8) << "recall" << std::setw(10) << "precision" << std::setw(13) << "centre_err/r"
      << std::setw(8) << "ms"
      << "\n";
  const auto row = [&out](const std::string& method, const std::string& what, const BoxMatch& match,
                          double ms) {
    out << std::left << std::setw(11) << method << std::setw(42) << what << std::right
        << std::setw(6) << match.labelled << std::setw(6) << match.detected << std::setw(6)
        << match.matched << std::setw(8) << fixed(recall(match), 3) << std::setw(10)
        << fixed(precision(match), 3) << std::setw(13)
        << fixed(median_or_zero(match.center_error_ratio), 3) << std::setw(8) << fixed(ms, 2)
        << "\n";
  };
  for (const TennisMethodResult& method : result.methods) {
    std::vector<double> ms;
    for (const PhotoResult& photo : method.photos) {
      row(method.method, photo.set + "/" + photo.file, photo.match, photo.milliseconds);
      ms.push_back(photo.milliseconds);
    }
    row(method.method, "all", method.total, median_or_zero(ms));
  }
  return out.str();
}

}  // namespace ballsight
