#include "ballsight/eval/tennis_sim.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "ballsight/core/error.hpp"
#include "ballsight/core/text_format.hpp"
#include "ballsight/eval/court_eval_scenes.hpp"
#include "ballsight/eval/detect_real.hpp"
#include "ballsight/sim/silhouette.hpp"

namespace ballsight {

namespace {

// The ranges of ball radius (px) the figures are broken down by (from 0: a box cut by the image
// border may be smaller than min_radius_px).
constexpr std::array<double, 8> kRadiusEdges{0.0, 2.0, 3.0, 4.0, 5.0, 7.0, 10.0, 20.0};

constexpr int kOutlineSamples = 32;

struct Labels {
  std::vector<LabelledBall> balls;
  std::vector<LabelledBall> others;  // every other sphere the frame holds
};

// Camera `c`'s labels: a box (pixel edges, clipped to the image) around the outline of every
// tennis ball shown (its centre in the image, half of it or more unhidden) at min_radius_px or
// more (half the outline's larger extent); every other sphere with its centre in the image or
// near it (a ball cut by the border is found by its visible part) in `others`.
Labels frame_labels(const sim::CourtCamera& camera, const std::vector<sim::SceneSphere>& spheres,
                    const std::vector<sim::SphereTruth>& truth, std::size_t c,
                    const TennisSimOptions& options) {
  const cv::Rect image(0, 0, options.rig.width, options.rig.height);
  Labels labels;
  for (std::size_t k = 0; k < spheres.size(); ++k) {
    const sim::SphereViewTruth& view = truth[k].views[c];
    const auto rim = sim::sphere_outline_pixels(
        camera.camera, camera.camera_from_field * spheres[k].center_in_field, spheres[k].radius_m,
        kOutlineSamples);
    if (!view.center_px || !rim) continue;
    double x0 = rim->front().x(), y0 = rim->front().y(), x1 = x0, y1 = y0;
    for (const Vec2& q : *rim) {
      x0 = std::min(x0, q.x()), y0 = std::min(y0, q.y());
      x1 = std::max(x1, q.x()), y1 = std::max(y1, q.y());
    }
    const double r = 0.5 * std::max(x1 - x0, y1 - y0);
    if (spheres[k].kind == sim::ObjectKind::tennis_ball && view.visible &&
        r >= options.min_radius_px) {
      labels.balls.push_back(
          label_of_box(cv::Rect(cv::Point(static_cast<int>(std::floor(x0 + 0.5)),
                                          static_cast<int>(std::floor(y0 + 0.5))),
                                cv::Point(static_cast<int>(std::ceil(x1 + 0.5)),
                                          static_cast<int>(std::ceil(y1 + 0.5)))) &
                       image));
    } else {
      labels.others.push_back({*view.center_px, r});
    }
  }
  return labels;
}

}  // namespace

void TennisSimOptions::validate() const {
  require(scenes >= 1 && scenes <= kMaxScenes, "scenes",
          "must be within [1, " + std::to_string(kMaxScenes) + "]");
  require(min_radius_px >= 1.0, "min_radius_px", "must be at least 1 pixel");
  court.validate();
  rig.validate();
  scenario.validate();
  detector.validate();
}

TennisSimResult run_tennis_sim(const TennisSimOptions& options) {
  options.validate();
  const CourtEvalScenes scenes(options.court, options.rig, options.seed);
  PhotoBallDetector detector(options.detector);
  TennisSimResult result{{{"ballsight", {}, {}}, {"report-hsv", {}, {}}}};
  for (int k = 0; k < options.scenes; ++k) {
    const auto [scene, renders, truth] = scenes.render(options.scenario, k);
    const std::string condition(sim::light_condition_name(scene.lighting.condition));
    const std::vector<sim::SceneSphere> spheres = scene.spheres();
    for (std::size_t c = 0; c < renders.size(); ++c) {
      const Labels labels = frame_labels(scenes.rig().cameras[c], spheres, truth, c, options);
      const cv::Mat& frame = renders[c].bgr;
      for (TennisSimMethod& method : result.methods) {
        const std::vector<PhotoBall> balls =
            method.method == "ballsight" ? detector.detect(frame) : report_hsv_balls(frame);
        const BallMatch match = match_balls_to_labels(
            labels.balls, without_ignored(balls, labels.balls, labels.others), frame.size());
        add_match(method.conditions[condition], match);
        add_match(method.total, match);
      }
    }
  }
  return result;
}

LabelledPhotos simulated_labelled_photos(const TennisSimOptions& options) {
  options.validate();
  const CourtEvalScenes scenes(options.court, options.rig, options.seed);
  LabelledPhotos photos{"simulator", {}, {}, {}, {}};
  for (int k = 0; k < options.scenes; ++k) {
    const auto [scene, renders, truth] = scenes.render(options.scenario, k);
    const std::vector<sim::SceneSphere> spheres = scene.spheres();
    for (std::size_t c = 0; c < renders.size(); ++c) {
      Labels labels = frame_labels(scenes.rig().cameras[c], spheres, truth, c, options);
      photos.files.push_back("scene" + std::to_string(k) + "_camera" + std::to_string(c) + ".png");
      photos.images.push_back(renders[c].bgr);
      photos.labels.push_back(std::move(labels.balls));
      photos.ignored.push_back(std::move(labels.others));
    }
  }
  return photos;
}

LabelledPhotos simulated_fitting_photos(int scenes, std::uint64_t seed) {
  TennisSimOptions options;
  options.scenes = scenes;
  options.seed = seed;
  options.rig.width = 1920;
  options.rig.height = 1080;
  options.scenario.distractors = true;
  return simulated_labelled_photos(options);
}

nlohmann::json tennis_sim_json(const TennisSimResult& result) {
  nlohmann::json methods = nlohmann::json::array();
  for (const TennisSimMethod& method : result.methods) {
    nlohmann::json m = ball_match_json(method.total);
    m["method"] = method.method;
    m["recall_by_radius"] = recall_by_radius_json(recall_by_radius(method.total, kRadiusEdges));
    for (const auto& [condition, match] : method.conditions)
      m["conditions"][condition] = ball_match_json(match);
    methods.push_back(m);
  }
  return {{"methods", methods}};
}

std::string tennis_sim_table(const TennisSimResult& result) {
  std::ostringstream out;
  out << std::left << std::setw(11) << "method" << std::setw(13) << "light" << std::right
      << std::setw(7) << "balls" << std::setw(7) << "found" << std::setw(7) << "match"
      << std::setw(8) << "recall" << std::setw(10) << "precision"
      << "\n";
  const auto row = [&out](const std::string& method, const std::string& light,
                          const BallMatch& match) {
    out << std::left << std::setw(11) << method << std::setw(13) << light << std::right
        << std::setw(7) << match.labelled << std::setw(7) << match.detected << std::setw(7)
        << match.matched << std::setw(8) << fixed(recall(match), 3) << std::setw(10)
        << fixed(precision(match), 3) << "\n";
  };
  for (const TennisSimMethod& method : result.methods) {
    for (const auto& [condition, match] : method.conditions) row(method.method, condition, match);
    row(method.method, "all", method.total);
  }
  out << "\nrecall by ball radius, px (balls)\n" << std::left << std::setw(11) << "method";
  for (const RadiusRecall& range : recall_by_radius({}, kRadiusEdges)) {
    std::string label = fixed(range.min_radius_px, 0);
    label += std::isfinite(range.max_radius_px) ? "-" : "+";
    if (std::isfinite(range.max_radius_px)) label += fixed(range.max_radius_px, 0);
    out << std::right << std::setw(13) << label;
  }
  out << "\n";
  for (const TennisSimMethod& method : result.methods) {
    out << std::left << std::setw(11) << method.method << std::right;
    for (const RadiusRecall& range : recall_by_radius(method.total, kRadiusEdges))
      out << std::setw(13)
          << (range.labelled > 0
                  ? fixed(recall(range), 3) + " (" + std::to_string(range.labelled) + ")"
                  : "-");
    out << "\n";
  }
  return out.str();
}

}  // namespace ballsight
