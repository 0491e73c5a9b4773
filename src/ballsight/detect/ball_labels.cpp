#include "ballsight/detect/ball_labels.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <sstream>

#include "ballsight/core/csv_fields.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/core/statistics.hpp"

namespace ballsight {

namespace fs = std::filesystem;

namespace {

constexpr const char* kHeader = "image,cx,cy,r";

bool is_image_file(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext == ".jpg" || ext == ".jpeg" || ext == ".png";
}

// The centre of what is visible of `ball`: its circle's box (pixel edges) clipped to the image.
Vec2 visible_center(const PhotoBall& ball, cv::Size image_size) {
  const double x0 = std::max(0.0, ball.center_px.x() + 0.5 - ball.radius_px);
  const double y0 = std::max(0.0, ball.center_px.y() + 0.5 - ball.radius_px);
  const double x1 = std::min<double>(image_size.width, ball.center_px.x() + 0.5 + ball.radius_px);
  const double y1 = std::min<double>(image_size.height, ball.center_px.y() + 0.5 + ball.radius_px);
  return Vec2(0.5 * (x0 + x1) - 0.5, 0.5 * (y0 + y1) - 0.5);
}

double median_or_zero(const std::vector<double>& values) {
  return values.empty() ? 0.0 : median(values);
}

}  // namespace

std::vector<LabelRow> parse_ball_labels(std::string_view csv, const std::string& where) {
  std::istringstream text{std::string(csv)};
  std::string line;
  std::getline(text, line);
  require(trim_blanks(line) == kHeader, where + ":1",
          std::string("expected the header ") + kHeader);
  std::vector<LabelRow> rows;
  for (int number = 2; std::getline(text, line); ++number) {
    if (trim_blanks(line).empty()) continue;
    const std::string at = where + ":" + std::to_string(number);
    const std::vector<CsvField> fields = split_csv_fields(line);
    require(fields.size() == 4 && !fields[0].text.empty(), at,
            "expected an image name, cx, cy and r");
    const LabelledBall ball{Vec2(csv_number(fields[1], at), csv_number(fields[2], at)),
                            csv_number(fields[3], at)};
    require(ball.radius_px > 0.0, at, "expected a radius above 0");
    rows.push_back({std::string(fields[0].text), ball, number});
  }
  return rows;
}

LabelledSource read_labelled_source(const fs::path& folder) {
  LabelledSource source;
  source.name = folder.filename().string();
  source.images_dir = folder / "images";
  const fs::path csv = folder / "labels.csv";
  std::map<std::string, std::vector<LabelledBall>> balls;
  std::error_code error;
  require(fs::is_directory(source.images_dir, error), source.images_dir.string(),
          "is not a folder of images");
  for (const fs::directory_entry& entry : fs::directory_iterator(source.images_dir))
    if (entry.is_regular_file() && is_image_file(entry.path()))
      balls[entry.path().filename().string()];
  for (const LabelRow& row : parse_ball_labels(read_file(csv), csv.string())) {
    const auto it = balls.find(row.image);
    require(it != balls.end(), csv.string() + ":" + std::to_string(row.line),
            "names " + row.image + ", which is not an image of " + source.images_dir.string());
    it->second.push_back(row.ball);
  }
  for (auto& [file, labels] : balls) source.images.push_back({file, std::move(labels)});
  require(!source.images.empty(), source.images_dir.string(), "holds no image");
  return source;
}

std::vector<LabelledSource> read_labelled_sources(const fs::path& root) {
  std::vector<LabelledSource> sources;
  std::error_code error;
  if (!fs::is_directory(root, error)) return sources;
  std::vector<fs::path> folders;
  for (const fs::directory_entry& entry : fs::directory_iterator(root))
    if (entry.is_directory() && fs::exists(entry.path() / "labels.csv")) folders.push_back(entry);
  std::sort(folders.begin(), folders.end());
  for (const fs::path& folder : folders) sources.push_back(read_labelled_source(folder));
  return sources;
}

LabelledBall label_of_box(const cv::Rect2d& box) {
  return {Vec2(box.x + 0.5 * box.width - 0.5, box.y + 0.5 * box.height - 0.5),
          0.25 * (box.width + box.height)};
}

std::vector<PhotoBall> without_ignored(std::span<const PhotoBall> balls,
                                       std::span<const LabelledBall> labels,
                                       std::span<const LabelledBall> ignored) {
  const auto within = [](const PhotoBall& ball, const LabelledBall& label, double margin) {
    return (ball.center_px - label.center_px).norm() <= label.radius_px + margin;
  };
  std::vector<PhotoBall> kept;
  for (const PhotoBall& ball : balls) {
    const bool on_label = std::any_of(labels.begin(), labels.end(),
                                      [&](const LabelledBall& l) { return within(ball, l, 0.0); });
    const bool on_ignored = std::any_of(ignored.begin(), ignored.end(), [&](const LabelledBall& o) {
      return within(ball, o, kIgnoredMarginPx);
    });
    if (on_label || !on_ignored) kept.push_back(ball);
  }
  return kept;
}

BallMatch match_balls_to_labels(std::span<const LabelledBall> labels,
                                std::span<const PhotoBall> balls, cv::Size image_size) {
  BallMatch match;
  match.labelled = static_cast<int>(labels.size());
  match.detected = static_cast<int>(balls.size());
  match.label_matched.assign(labels.size(), false);
  for (const LabelledBall& label : labels) match.label_radius_px.push_back(label.radius_px);
  std::vector<PhotoBall> best_first(balls.begin(), balls.end());
  std::stable_sort(best_first.begin(), best_first.end(),
                   [](const PhotoBall& a, const PhotoBall& b) { return a.score > b.score; });
  for (const PhotoBall& ball : best_first) {
    const Vec2 c = visible_center(ball, image_size);
    std::size_t best = labels.size();
    double best_distance = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < labels.size(); ++k) {
      const double distance = (c - labels[k].center_px).norm();
      if (!match.label_matched[k] && distance <= labels[k].radius_px && distance < best_distance)
        best = k, best_distance = distance;
    }
    if (best == labels.size()) continue;
    match.label_matched[best] = true;
    ++match.matched;
    match.center_error_px.push_back(best_distance);
    match.center_error_radii.push_back(best_distance / labels[best].radius_px);
  }
  return match;
}

void add_match(BallMatch& total, const BallMatch& part) {
  total.labelled += part.labelled;
  total.detected += part.detected;
  total.matched += part.matched;
  const auto append = [](auto& to, const auto& from) {
    to.insert(to.end(), from.begin(), from.end());
  };
  append(total.center_error_px, part.center_error_px);
  append(total.center_error_radii, part.center_error_radii);
  append(total.label_radius_px, part.label_radius_px);
  append(total.label_matched, part.label_matched);
}

double recall(const BallMatch& match) {
  return match.labelled > 0 ? static_cast<double>(match.matched) / match.labelled : 1.0;
}

double precision(const BallMatch& match) {
  return match.detected > 0 ? static_cast<double>(match.matched) / match.detected : 1.0;
}

double f1_score(const BallMatch& match) {
  const int denominator = match.labelled + match.detected;
  return denominator > 0 ? 2.0 * match.matched / denominator : 1.0;
}

double recall(const RadiusRecall& range) {
  return range.labelled > 0 ? static_cast<double>(range.matched) / range.labelled : 1.0;
}

std::vector<RadiusRecall> recall_by_radius(const BallMatch& match, std::span<const double> edges) {
  require(std::adjacent_find(edges.begin(), edges.end(), std::greater_equal<>()) == edges.end(),
          "radius ranges", "edges must be strictly ascending");
  std::vector<RadiusRecall> ranges;
  for (std::size_t k = 0; k < edges.size(); ++k)
    ranges.push_back({edges[k],
                      k + 1 < edges.size() ? edges[k + 1] : std::numeric_limits<double>::infinity(),
                      0, 0});
  for (std::size_t b = 0; b < match.label_radius_px.size(); ++b)
    for (RadiusRecall& range : ranges)
      if (match.label_radius_px[b] >= range.min_radius_px &&
          match.label_radius_px[b] < range.max_radius_px) {
        ++range.labelled;
        range.matched += match.label_matched[b];
      }
  return ranges;
}

nlohmann::json ball_match_json(const BallMatch& match) {
  return {{"labelled", match.labelled},
          {"detected", match.detected},
          {"matched", match.matched},
          {"recall", recall(match)},
          {"precision", precision(match)},
          {"f1", f1_score(match)},
          {"median_center_error_px", median_or_zero(match.center_error_px)},
          {"median_center_error_radii", median_or_zero(match.center_error_radii)}};
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

}  // namespace ballsight
