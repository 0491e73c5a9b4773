#include "ballsight/eval/detect_real.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iomanip>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <sstream>

#include "ballsight/camera/image_file.hpp"
#include "ballsight/core/enum_names.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/core/statistics.hpp"
#include "ballsight/core/text_format.hpp"
#include "ballsight/detect/ball_verifier.hpp"
#include "ballsight/detect/photo_ball_fit.hpp"
#include "ballsight/detect/seed_detector.hpp"
#include "ballsight/eval/tennis_sim.hpp"

namespace ballsight {

namespace fs = std::filesystem;

namespace {

constexpr double kSmallRadiusPx = 4.0;
constexpr double kInnerDisc = 0.7;
constexpr double kMinGrowthShare = 0.5;

using Detector = std::function<std::vector<PhotoBall>(const cv::Mat&)>;

void draw(const fs::path& path, const cv::Mat& bgr, std::span<const LabelledBall> labels,
          std::span<const PhotoBall> balls) {
  cv::Mat plot = bgr.clone();
  const auto point = [](const Vec2& p) {
    return cv::Point(static_cast<int>(std::lround(p.x() * 4)),
                     static_cast<int>(std::lround(p.y() * 4)));
  };
  for (const LabelledBall& label : labels)
    cv::circle(plot, point(label.center_px), static_cast<int>(std::lround(label.radius_px * 4)),
               {0, 255, 0}, 1, cv::LINE_AA, 2);
  for (const PhotoBall& ball : balls)
    cv::circle(plot, point(ball.center_px), static_cast<int>(std::lround(ball.radius_px * 4)),
               {255, 0, 255}, 1, cv::LINE_AA, 2);
  ensure_directory(path.parent_path());
  write_png_atomic(path, plot);
}

SourceScore score_source(const std::string& method, const Detector& detect,
                         const LabelledPhotos& photos, const ColorClassTable& growth,
                         const fs::path& draw_dir) {
  SourceScore score{photos.source, {}, {}, 0.0, {}};
  std::vector<double> ms;
  for (std::size_t i = 0; i < photos.images.size(); ++i) {
    const cv::Mat& bgr = photos.images[i];
    const std::vector<LabelledBall>& labels = photos.labels[i];
    const auto start = std::chrono::steady_clock::now();
    const std::vector<PhotoBall> balls = detect(bgr);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                     .count());
    const BallMatch match = match_balls_to_labels(labels, balls, bgr.size());
    for (std::size_t k = 0; k < labels.size(); ++k)
      if (!match.label_matched[k])
        ++score.misses[static_cast<std::size_t>(miss_cause(bgr, labels, k, growth))];
    add_match(score.match, match);
    if (!draw_dir.empty())
      draw(draw_dir / method / photos.source / (fs::path(photos.files[i]).stem().string() + ".png"),
           bgr, labels, balls);
  }
  score.median_milliseconds = median(ms);
  return score;
}

SourceScore score_detector(const std::string& method, const PhotoBallOptions& settings,
                           const LabelledPhotos& photos, const ColorClassTable& growth,
                           const fs::path& draw_dir) {
  PhotoBallDetector detector(settings);
  return score_source(
      method, [&detector](const cv::Mat& bgr) { return detector.detect(bgr); }, photos, growth,
      draw_dir);
}

// Every item of `items` but the one at `left_out`, in order.
template <typename T>
std::vector<T> all_but(const std::vector<T>& items, std::size_t left_out) {
  std::vector<T> out;
  for (std::size_t i = 0; i < items.size(); ++i)
    if (i != left_out) out.push_back(items[i]);
  return out;
}

// The verified method on sources[s], its threshold fitted on the other sources. The source's
// photos are verified again as they are scored, so that their time is measured.
SourceScore score_verified(const std::vector<LabelledPhotos>& sources,
                           const std::vector<std::vector<VerifiedPhoto>>& verified, std::size_t s,
                           const PhotoBallOptions& shipped, BallVerifier& verifier,
                           const ColorClassTable& growth, const fs::path& draw_dir) {
  const double min_probability = fit_min_probability(all_but(sources, s), all_but(verified, s));
  PhotoBallDetector detector(shipped);
  SourceScore score = score_source(
      kDetectRealMethods[3],
      [&](const cv::Mat& bgr) {
        return with_verified_candidates(verify_photo(detector, verifier, bgr), min_probability);
      },
      sources[s], growth, draw_dir);
  score.fit = {{"min_probability", min_probability}};
  return score;
}

constexpr EnumNames<MissCause, kMissCauses> kMissCauseNames{{{MissCause::border, "border"},
                                                             {MissCause::small, "small"},
                                                             {MissCause::touching, "touching"},
                                                             {MissCause::off_colour, "off_colour"},
                                                             {MissCause::other, "other"}}};

nlohmann::json misses_json(const std::array<int, kMissCauses>& misses) {
  nlohmann::json json = nlohmann::json::object();
  for (std::size_t c = 0; c < kMissCauses; ++c)
    json[std::string(miss_cause_name(static_cast<MissCause>(c)))] = misses[c];
  return json;
}

}  // namespace

std::string_view miss_cause_name(MissCause cause) {
  return enum_name(kMissCauseNames, cause);
}

MissCause miss_cause(const cv::Mat& bgr, std::span<const LabelledBall> labels, std::size_t k,
                     const ColorClassTable& growth) {
  const LabelledBall& label = labels[k];
  const Vec2& c = label.center_px;
  const double r = label.radius_px;
  if (c.x() - r < 0.5 || c.y() - r < 0.5 || c.x() + r > bgr.cols - 1.5 ||
      c.y() + r > bgr.rows - 1.5)
    return MissCause::border;
  if (r < kSmallRadiusPx) return MissCause::small;
  for (std::size_t j = 0; j < labels.size(); ++j)
    if (j != k && (labels[j].center_px - c).norm() <= labels[j].radius_px + r)
      return MissCause::touching;
  const double inner = kInnerDisc * r;
  int pixels = 0, grown = 0;
  for (int y = static_cast<int>(std::ceil(c.y() - inner)); y <= c.y() + inner; ++y)
    for (int x = static_cast<int>(std::ceil(c.x() - inner)); x <= c.x() + inner; ++x) {
      if (x < 0 || y < 0 || x >= bgr.cols || y >= bgr.rows ||
          (Vec2(x, y) - c).squaredNorm() > inner * inner)
        continue;
      ++pixels;
      grown += (growth.classify(bgr.at<cv::Vec3b>(y, x)) & kBallGrowClass) != 0;
    }
  if (pixels > 0 && grown < kMinGrowthShare * pixels) return MissCause::off_colour;
  return MissCause::other;
}

std::vector<PhotoBall> report_hsv_balls(const cv::Mat& bgr) {
  const SeedDetectorOptions options;
  std::vector<PhotoBall> balls;
  for (const PixelDetection& d :
       detect_seed_colour(bgr, options.ball, options.median_kernel_px, ObjectClass::ball))
    balls.push_back({d.center_px, d.radius_px, 1.0});
  return balls;
}

DetectRealResult run_detect_real(const DetectRealOptions& options) {
  options.shipped.validate();
  options.fit.validate();
  for (const std::string& method : options.methods)
    require(std::find(kDetectRealMethods.begin(), kDetectRealMethods.end(), method) !=
                kDetectRealMethods.end(),
            "methods", "unknown method " + method);
  const auto wanted = [&](const char* method) {
    return std::find(options.methods.begin(), options.methods.end(), method) !=
           options.methods.end();
  };
  const fs::path root = options.data_dir / "real" / "tennis";
  const std::vector<LabelledPhotos> sources = read_photo_sources(root, {}, "--data").others;
  require(!sources.empty(), root.string(), "holds no labelled source (*/labels.csv)");
  DetectRealResult result;
  for (const char* method : kDetectRealMethods)
    if (wanted(method)) result.methods.push_back({method, {}});
  const ColorClassTable growth = ball_colour_table(options.shipped.colours);
  const auto add = [&](const char* method, SourceScore score) {
    for (DetectRealMethod& m : result.methods)
      if (m.method == method) m.sources.push_back(std::move(score));
  };
  require(options.sim_scenes >= 0, "sim_scenes", "must be 0 or more");
  const std::optional<LabelledPhotos> simulated =
      options.sim_scenes > 0 && wanted(kDetectRealMethods[0])
          ? std::optional(simulated_fitting_photos(options.sim_scenes))
          : std::nullopt;
  std::optional<BallVerifier> verifier;
  std::vector<std::vector<VerifiedPhoto>> verified;  // per source
  if (wanted(kDetectRealMethods[3])) {
    require(!options.verifier.empty(), "methods", "verified needs a verifier model (--verifier)");
    verifier = BallVerifier::read(options.verifier);
    PhotoBallDetector detector(options.shipped);
    // With a single source there is nothing to fit the threshold on: no figure.
    if (sources.size() > 1)
      for (const LabelledPhotos& source : sources)
        verified.push_back(verify_photos(detector, *verifier, source));
  }
  for (std::size_t s = 0; s < sources.size(); ++s) {
    std::vector<LabelledPhotos> others = all_but(sources, s);
    if (simulated) others.push_back(*simulated);
    if (wanted(kDetectRealMethods[0]) && others.size() > (simulated ? 1u : 0u)) {
      const PhotoBallFit fit = fit_photo_ball_detector(others, options.fit);
      SourceScore score =
          score_detector(kDetectRealMethods[0], fit.options, sources[s], growth, options.draw_dir);
      score.fit = photo_ball_fit_json(fit);
      add(kDetectRealMethods[0], std::move(score));
    }
    if (wanted(kDetectRealMethods[1]))
      add(kDetectRealMethods[1], score_detector(kDetectRealMethods[1], options.shipped, sources[s],
                                                growth, options.draw_dir));
    if (wanted(kDetectRealMethods[2]))
      add(kDetectRealMethods[2], score_source(kDetectRealMethods[2], report_hsv_balls, sources[s],
                                              growth, options.draw_dir));
    if (!verified.empty())
      add(kDetectRealMethods[3], score_verified(sources, verified, s, options.shipped, *verifier,
                                                growth, options.draw_dir));
  }
  return result;
}

nlohmann::json detect_real_json(const DetectRealResult& result) {
  nlohmann::json methods = nlohmann::json::array();
  for (const DetectRealMethod& method : result.methods) {
    nlohmann::json sources = nlohmann::json::array();
    for (const SourceScore& score : method.sources) {
      nlohmann::json s = ball_match_json(score.match);
      s["source"] = score.source;
      s["misses"] = misses_json(score.misses);
      s["median_milliseconds"] = score.median_milliseconds;
      if (!score.fit.is_null()) s["fitted_without_it"] = score.fit;
      sources.push_back(s);
    }
    methods.push_back({{"method", method.method}, {"sources", sources}});
  }
  return {{"methods", methods}};
}

std::string detect_real_table(const DetectRealResult& result) {
  std::ostringstream out;
  out << std::left << std::setw(22) << "method" << std::setw(32) << "source" << std::right
      << std::setw(7) << "labels" << std::setw(6) << "found" << std::setw(6) << "match"
      << std::setw(8) << "recall" << std::setw(8) << "prec" << std::setw(7) << "F1" << std::setw(8)
      << "err_px" << std::setw(7) << "err/r"
      << "  misses\n";
  for (const DetectRealMethod& method : result.methods)
    for (const SourceScore& s : method.sources) {
      const nlohmann::json m = ball_match_json(s.match);
      out << std::left << std::setw(22) << method.method << std::setw(32) << s.source << std::right
          << std::setw(7) << s.match.labelled << std::setw(6) << s.match.detected << std::setw(6)
          << s.match.matched << std::setw(8) << fixed(recall(s.match), 3) << std::setw(8)
          << fixed(precision(s.match), 3) << std::setw(7) << fixed(f1_score(s.match), 3)
          << std::setw(8) << fixed(m["median_center_error_px"].get<double>(), 2) << std::setw(7)
          << fixed(m["median_center_error_radii"].get<double>(), 2) << "  "
          << misses_json(s.misses).dump() << "\n";
    }
  return out.str();
}

}  // namespace ballsight
