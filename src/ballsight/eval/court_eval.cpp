#include "ballsight/eval/court_eval.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <sstream>

#include "ballsight/camera/image_file.hpp"
#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/core/text_format.hpp"
#include "ballsight/eval/court_eval_scenes.hpp"
#include "ballsight/eval/plot_inputs.hpp"
#include "ballsight/eval/wall_clock.hpp"
#include "ballsight/pipeline/site_setup.hpp"
#include "ballsight/viz/court_plots.hpp"

namespace ballsight {

void CourtEvalOptions::validate() const {
  require(scenes >= 1 && scenes <= kMaxScenes, "scenes",
          "must be in [1, " + std::to_string(kMaxScenes) + "], got " + std::to_string(scenes));
  court.validate();
  rig.validate();
  scenario.validate();
  require(chessboard_views >= 4 && chessboard_views <= 99, "chessboard_views",
          "must be in [4, 99], got " + std::to_string(chessboard_views));
  require(match_radius_m > 0.0, "match_radius_m", "must be positive");
  require(plot_scenes >= 0, "plot_scenes", "must be non-negative");
}

namespace {

std::vector<TruthBall> truth_balls(const std::vector<sim::SphereTruth>& truth) {
  std::vector<TruthBall> balls;
  for (const sim::SphereTruth& t : truth) {
    if (t.sphere.kind != sim::ObjectKind::tennis_ball) continue;
    bool seen = false;
    for (const sim::SphereViewTruth& v : t.views) seen |= v.visible;
    balls.push_back({t.sphere.center_in_field.head<2>(), seen});
  }
  return balls;
}

std::vector<Vec2> truth_pixels(const std::vector<sim::SphereTruth>& truth, size_t camera) {
  std::vector<Vec2> pixels;
  for (const sim::SphereTruth& t : truth) {
    const sim::SphereViewTruth& v = t.views[camera];
    if (t.sphere.kind == sim::ObjectKind::tennis_ball && v.visible && v.silhouette_centroid_px)
      pixels.push_back(*v.silhouette_centroid_px);
  }
  return pixels;
}

// Where camera `camera` shows the true balls of the `missed` mistakes (the tennis ball whose
// centre is nearest each one's position; where it is in view).
std::vector<Vec2> missed_pixels(const std::vector<sim::SphereTruth>& truth,
                                const std::vector<BallMistake>& mistakes, size_t camera) {
  std::vector<Vec2> pixels;
  for (const BallMistake& mistake : mistakes) {
    if (mistake.kind != BallMistake::Kind::missed) continue;
    const sim::SphereTruth* nearest = nullptr;
    double best = std::numeric_limits<double>::infinity();
    for (const sim::SphereTruth& t : truth) {
      const double d = (t.sphere.center_in_field.head<2>() - mistake.position_m).norm();
      if (t.sphere.kind == sim::ObjectKind::tennis_ball && d < best) {
        best = d;
        nearest = &t;
      }
    }
    if (!nearest) continue;
    const sim::SphereViewTruth& v = nearest->views[camera];
    if (v.visible && v.silhouette_centroid_px) pixels.push_back(*v.silhouette_centroid_px);
  }
  return pixels;
}

const cv::Scalar kSeedColour(40, 40, 230);       // red
const cv::Scalar kBallsightColour(40, 200, 40);  // green

std::string scene_name(int scene) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "scene_%04d", scene);
  return buffer;
}

void write_pictures(const CourtEvalOptions& options, const sim::CourtRig& rig, int scene,
                    const std::vector<cv::Mat>& frames, const std::vector<sim::SphereTruth>& truth,
                    const Pose2D& robot_truth, const std::vector<FrameSetResult>& results,
                    const std::vector<BallMistake>& ballsight_mistakes,
                    std::vector<std::string>& written) {
  const std::filesystem::path& dir = *options.plot_dir;
  ensure_directory(dir);
  for (size_t c = 0; c < frames.size(); ++c) {
    std::vector<DetectionLayer> layers;
    for (size_t m = 0; m < results.size(); ++m) {
      const auto& detections = results[m].detections[c];
      layers.push_back({m == 0 ? "seed pipeline" : "ballsight",
                        m == 0 ? kSeedColour : kBallsightColour,
                        detections ? *detections : std::vector<PixelDetection>{}});
    }
    const std::string name = scene_name(scene) + "_cam" + std::to_string(c) + ".png";
    write_png_atomic(dir / name,
                     draw_detection_overlay(frames[c], truth_pixels(truth, c), layers,
                                            missed_pixels(truth, ballsight_mistakes, c),
                                            scene_name(scene) + ", camera " + std::to_string(c)));
    written.push_back(name);
  }
  std::vector<Vec3> centers;
  for (const sim::CourtCamera& camera : rig.cameras) centers.push_back(camera.center_in_field());
  std::vector<WorldLayer> layers;
  for (size_t m = 0; m < results.size(); ++m)
    layers.push_back({m == 0 ? "seed pipeline" : "ballsight (circles: collection sites)",
                      m == 0 ? kSeedColour : kBallsightColour, results[m].world,
                      m == 0 ? std::vector<MistakeMark>{} : mistake_marks(ballsight_mistakes)});
  const std::string name = scene_name(scene) + "_field.png";
  write_png_atomic(dir / name, draw_field_map(court_floor(rig.court), centers,
                                              true_ball_marks(truth_balls(truth)), robot_truth,
                                              layers, scene_name(scene) + ": truth vs estimates"));
  written.push_back(name);
}

}  // namespace

CourtEvalReport run_court_eval(const CourtEvalOptions& options) {
  options.validate();
  CourtEvalReport report;
  report.options = options;
  const CourtEvalScenes scenes(options.court, options.rig, options.seed);
  const sim::CourtRig& rig = scenes.rig();

  // Each method calibrates its cameras from the same rendered images.
  const CalibrationImages calibration_images =
      render_calibration_images(rig, options.chessboard_views, options.scenario.noise_sigma,
                                court_eval_calibration_seed(options.seed));
  const Site site = simulated_site(rig);
  // A method that cannot calibrate (too few reference balls found, say) is reported as such.
  std::vector<std::unique_ptr<CourtPipeline>> pipelines;
  for (const CourtMethod method : {CourtMethod::seed, CourtMethod::ballsight}) {
    MethodReport& m = report.methods.emplace_back();
    m.method = method;
    try {
      if (method == CourtMethod::seed) {
        m.calibration = calibrate_seed_cameras(calibration_images, site);
        pipelines.push_back(make_seed_pipeline(m.calibration.cameras, seed_options_for_site(site)));
      } else {
        m.calibration = calibrate_ballsight_cameras(calibration_images, site);
        pipelines.push_back(
            make_ballsight_pipeline(m.calibration.cameras, ballsight_options_for_site(site)));
      }
    } catch (const InputError& e) {
      m.calibration_error = e.what();
      pipelines.push_back(nullptr);
    }
  }

  for (int k = 0; k < options.scenes; ++k) {
    const auto [scene, renders, truth] = scenes.render(options.scenario, k);
    std::vector<cv::Mat> images;
    for (const sim::CourtRender& render : renders) images.push_back(render.bgr);
    const FrameSet frames = frame_set_of(images, 0);  // Mat headers: the pixels are shared
    const std::vector<TruthBall> balls = truth_balls(truth);
    std::vector<FrameSetResult> results;
    std::vector<BallMistake> ballsight_mistakes;
    for (size_t m = 0; m < pipelines.size(); ++m) {
      if (!pipelines[m]) {
        FrameSetResult nothing;
        nothing.detections.resize(frames.cameras.size());
        results.push_back(std::move(nothing));
        continue;
      }
      const auto start = std::chrono::steady_clock::now();
      results.push_back(pipelines[m]->process(frames));
      const std::chrono::duration<double, std::milli> elapsed =
          std::chrono::steady_clock::now() - start;
      MethodReport& method = report.methods[m];
      method.frame_set_ms.push_back(elapsed.count());
      std::vector<Vec2> estimates;
      for (const FusedBall& ball : results.back().world.balls) estimates.push_back(ball.position_m);
      const WorldModel& world = results.back().world;
      const SceneScore score =
          score_scene(balls, estimates, scene.robot.pose,
                      world.robot ? std::optional<Pose2D>(world.robot->pose) : std::nullopt,
                      options.match_radius_m);
      if (method.method == CourtMethod::ballsight) ballsight_mistakes = score.mistakes;
      method.scores.add(score);
      method.by_condition[std::string(sim::light_condition_name(scene.lighting.condition))].add(
          score);
    }
    if (options.plot_dir &&
        (k < options.plot_scenes || (options.plot_mistakes && !ballsight_mistakes.empty())))
      write_pictures(options, rig, k, images, truth, scene.robot.pose, results, ballsight_mistakes,
                     report.pictures);
  }
  return report;
}

namespace {

nlohmann::json finite_or_null(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

// The ball and robot figures of `s`.
nlohmann::json scores_json(const CourtScores& s) {
  nlohmann::json j;
  j["scenes"] = s.scenes;
  j["recall"] = finite_or_null(s.recall());
  j["precision"] = finite_or_null(s.precision());
  j["duplicates"] = s.duplicates;
  j["false_positives"] = s.false_positives;
  j["ball_error_mean_cm"] = finite_or_null(100.0 * s.ball_error_mean_m());
  j["ball_error_p95_cm"] = finite_or_null(100.0 * s.ball_error_p95_m());
  j["robot_position_error_cm"] = finite_or_null(100.0 * s.robot_position_error_mean_m());
  j["robot_position_error_max_cm"] = finite_or_null(100.0 * s.robot_position_error_max_m());
  j["robot_heading_error_deg"] = finite_or_null(deg_from_rad(s.robot_heading_error_mean_rad()));
  j["robot_heading_error_max_deg"] = finite_or_null(deg_from_rad(s.robot_heading_error_max_rad()));
  j["robot_found_scenes"] = s.robot_found;
  j["balls_counted"] = s.counted;
  j["balls_unseen"] = s.unseen;
  j["estimates"] = s.estimates;
  j["true_positives"] = s.true_positives;
  j["correct_extras"] = s.correct_extras;
  return j;
}

}  // namespace

nlohmann::json court_eval_json(const CourtEvalReport& report) {
  nlohmann::json methods = nlohmann::json::object();
  for (const MethodReport& m : report.methods) {
    const CourtScores& s = m.scores;
    nlohmann::json j = scores_json(s);
    nlohmann::json conditions = nlohmann::json::object();
    for (const auto& [name, scores] : m.by_condition) conditions[name] = scores_json(scores);
    j["by_condition"] = conditions;
    j["frame_set_ms_mean"] =
        finite_or_null(m.frame_set_ms.empty()
                           ? NAN
                           : std::accumulate(m.frame_set_ms.begin(), m.frame_set_ms.end(), 0.0) /
                                 static_cast<double>(m.frame_set_ms.size()));
    j["calibration"] = {{"intrinsics_rms_px", m.calibration.intrinsics_rms_px},
                        {"pose_rms_px", m.calibration.pose_rms_px}};
    nlohmann::json mistakes = nlohmann::json::array();
    for (const BallMistake& mistake : s.mistakes)
      mistakes.push_back({{"scene", mistake.scene},
                          {"kind", mistake_kind_name(mistake.kind)},
                          {"x_m", mistake.position_m.x()},
                          {"y_m", mistake.position_m.y()}});
    j["mistakes"] = mistakes;
    if (!m.calibration_error.empty()) j["calibration_error"] = m.calibration_error;
    methods[court_method_name(m.method)] = j;
  }
  nlohmann::json out;
  out["methods"] = methods;
  out["seed"] = report.options.seed;
  out["scenes"] = report.options.scenes;
  out["match_radius_m"] = report.options.match_radius_m;
  out["pictures"] = report.pictures;
  return with_wall_clock_apart(std::move(out), {"frame_set_ms_mean"});
}

namespace {

// One row of the table without its time: recall, precision, duplicates, false positives, ball
// and robot errors.
std::string scores_line(const std::string& name, const CourtScores& s) {
  char line[256];
  // The robot's errors are over the scenes where it was found: how many is said beside them.
  std::snprintf(
      line, sizeof line,
      "%-10s %6.2f%%  %8.2f%%  %3d %3d  %5.2f cm  %5.2f cm  %6.2f cm  %6.3f deg  %3d/%-3d",
      name.c_str(), 100.0 * s.recall(), 100.0 * s.precision(), s.duplicates, s.false_positives,
      100.0 * s.ball_error_mean_m(), 100.0 * s.ball_error_p95_m(),
      100.0 * s.robot_position_error_mean_m(), deg_from_rad(s.robot_heading_error_mean_rad()),
      s.robot_found, s.scenes);
  return line;
}

}  // namespace

std::string court_eval_text(const CourtEvalReport& report) {
  constexpr size_t kMistakesShown = 20;
  std::ostringstream out;
  char line[256];
  std::snprintf(line, sizeof line, "court evaluation: seed %llu, %d scenes, match radius %.0f cm\n",
                static_cast<unsigned long long>(report.options.seed), report.options.scenes,
                100.0 * report.options.match_radius_m);
  out << line;
  out << "method      recall  precision  dup  FP  err mean  err p95  robot pos  robot hdg  "
         "found    ms/set\n";
  for (const MethodReport& m : report.methods) {
    if (!m.calibration_error.empty()) {
      out << court_method_name(m.method) << ": could not be calibrated: " << m.calibration_error
          << "\n";
      continue;
    }
    const CourtScores& s = m.scores;
    double ms = 0.0;
    for (double v : m.frame_set_ms) ms += v / static_cast<double>(m.frame_set_ms.size());
    out << scores_line(court_method_name(m.method), s) << "  " << fixed(ms, 1) << "\n";
    for (const auto& [name, scores] : m.by_condition)
      out << scores_line("  " + name, scores) << "  (" << scores.scenes << " scenes)\n";
    if (m.method == CourtMethod::ballsight && !s.mistakes.empty()) {
      out << "  ballsight's mistakes (scene: kind at field position):\n";
      const size_t shown = std::min<size_t>(s.mistakes.size(), kMistakesShown);
      for (size_t i = 0; i < shown; ++i) {
        const BallMistake& mistake = s.mistakes[i];
        std::snprintf(line, sizeof line, "  scene %d: %s at (%.3f, %.3f) m\n", mistake.scene,
                      mistake_kind_name(mistake.kind).c_str(), mistake.position_m.x(),
                      mistake.position_m.y());
        out << line;
      }
      if (shown < s.mistakes.size())
        out << "  ... " << s.mistakes.size() - shown << " more (all in --json)\n";
    }
  }
  const CourtScores& any = std::max_element(report.methods.begin(), report.methods.end(),
                                            [](const auto& a, const auto& b) {
                                              return a.scores.scenes < b.scores.scenes;
                                            })
                               ->scores;
  std::snprintf(line, sizeof line,
                "balls: %d seen by at least one camera (counted for recall), %d seen by none\n",
                any.counted, any.unseen);
  out << line;
  for (const std::string& picture : report.pictures) out << "wrote " << picture << "\n";
  return out.str();
}

}  // namespace ballsight
