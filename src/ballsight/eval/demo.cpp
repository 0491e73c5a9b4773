#include "ballsight/eval/demo.hpp"

#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "ballsight/calib/ballsight_model.hpp"
#include "ballsight/calib/model_ground_map.hpp"
#include "ballsight/calib/polynomial_model.hpp"
#include "ballsight/camera/ground_map_io.hpp"
#include "ballsight/camera/image_file.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/core/text_format.hpp"
#include "ballsight/eval/court_eval.hpp"
#include "ballsight/eval/loop_demo.hpp"
#include "ballsight/eval/plan_eval.hpp"
#include "ballsight/eval/plot_inputs.hpp"
#include "ballsight/pipeline/marker_frame_samples.hpp"
#include "ballsight/pipeline/omni_pipelines.hpp"
#include "ballsight/sim/court_dataset.hpp"
#include "ballsight/sim/omni_dataset.hpp"
#include "ballsight/sim/omni_scenario.hpp"
#include "ballsight/sim/tennis_court.hpp"
#include "ballsight/viz/loop_plot.hpp"
#include "ballsight/viz/report.hpp"

namespace ballsight {

namespace fs = std::filesystem;

void DemoOptions::validate() const {
  require(omni_frames >= 1 && omni_frames <= 100, "demo", "omni_frames must be 1..100");
  require(court_scenes >= 1 && court_scenes <= 20, "demo", "court_scenes must be 1..20");
  require(loop_balls >= 1 && loop_balls <= 60, "--loop-balls", "must be 1..60");
  require(std::isfinite(loop_max_time_s) && loop_max_time_s > 0.0, "--loop-max-time",
          "must be positive");
}

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

bool is_png(const std::string& name) {
  return name.size() > 4 && name.ends_with(".png");
}

nlohmann::json read_json(const fs::path& path) {
  try {
    return nlohmann::json::parse(read_file(path));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path.string() + ": " + e.what());
  }
}

std::vector<ReportFigure> omni_figures(const fs::path& dir, const std::vector<std::string>& files) {
  std::vector<ReportFigure> figures;
  for (const std::string& name : files) {
    if (!is_png(name)) continue;
    const nlohmann::json truth = read_json(dir / (name.substr(0, name.size() - 4) + ".json"));
    const auto& robot = truth["robot"];
    std::string caption = "robot at (" + fixed(robot["position_m"][0], 2) + ", " +
                          fixed(robot["position_m"][1], 2) + ") m, heading " +
                          fixed(robot["heading_deg"], 1) + " deg; ";
    if (truth["ball"].is_object()) {
      caption += "ball " + fixed(truth["ball"]["distance_m"], 2) + " m away at bearing " +
                 fixed(truth["ball"]["bearing_deg"], 1) + " deg";
    } else {
      caption += std::to_string(truth["markers"].size()) + " calibration markers";
    }
    figures.push_back({"omni/" + name, caption});
  }
  return figures;
}

// The omni run time on the data set: calibrated without clicking from frame 0's markers, then the
// ball of every other frame placed by ballsight's pipeline and by the paper's (polynomial, as its
// robots), against the truth. Appends to the frames' captions; returns the summary.
std::string omni_localisation(const fs::path& dir, std::vector<ReportFigure>& figures) {
  const auto start = Clock::now();
  const sim::OmniPalette palette;
  const Vec2 configured_center(319.5, 239.5);
  const std::vector<LayoutMarker> layout = layout_markers();
  const cv::Mat calibration_frame = read_image_bgr(dir / "omni_0000.png");
  const MarkerFrameSamples found =
      samples_from_marker_frame(calibration_frame, layout, palette.marker_bgr, configured_center);
  const OmniImage image{calibration_frame.cols, calibration_frame.rows, configured_center};
  const GroundMap map = ground_map_from_model(fit_ballsight_model(found.samples, image));
  save_ground_map(dir / "ballsight.bsgm", map);
  const double calibration_seconds = seconds_since(start);

  const PolynomialGroundModel poly = fit_polynomial_model(found.samples, image, {});
  const YuvRange ball_color = yuv_range_around(palette.ball_bgr);
  const BallsightOmniPipeline ballsight(ball_color, map, BallOnFloor{});
  const PaperOmniPipeline paper(ball_color, configured_center,
                                [&](double theta, double r) -> std::optional<double> {
                                  const double d = poly.predict(theta, r).distance_cm;
                                  return std::isfinite(d) ? std::optional(d) : std::nullopt;
                                });
  std::vector<double> ballsight_errors, paper_errors;
  for (ReportFigure& figure : figures) {
    const fs::path png = dir / fs::path(figure.image).filename();
    const nlohmann::json truth = read_json(fs::path(png).replace_extension(".json"));
    if (!truth["ball"].is_object()) continue;
    const auto& p = truth["ball"]["position_in_robot_m"];
    const Vec2 ball_cm(100.0 * p[0].get<double>(), 100.0 * p[1].get<double>());
    const cv::Mat frame = read_image_bgr(png);
    const auto describe = [&](const std::string& name, const std::optional<Vec2>& estimate,
                              std::vector<double>& errors) {
      if (!estimate) return "; " + name + ": not found";
      errors.push_back((*estimate - ball_cm).norm());
      return "; " + name + ": error " + fixed(errors.back(), 1) + " cm";
    };
    figure.caption += describe("ballsight", ballsight.locate_in_robot_cm(frame), ballsight_errors);
    figure.caption +=
        describe("paper's pipeline (poly)", paper.locate_cm(frame, Pose2D{}), paper_errors);
  }
  const auto mean = [](const std::vector<double>& v) {
    double sum = 0.0;
    for (double x : v) sum += x;
    return v.empty() ? 0.0 : sum / static_cast<double>(v.size());
  };
  return "Calibrated without clicking: " + std::to_string(found.samples.size()) + " of " +
         std::to_string(layout.size()) + " markers found in frame 0 and matched to the paper's " +
         "layout, ballsight's model fitted and baked into omni/ballsight.bsgm in " +
         fixed(calibration_seconds, 2) + " s (docs/omni-calibration.md). Ball error: ballsight " +
         fixed(mean(ballsight_errors), 2) + " cm mean over " +
         std::to_string(ballsight_errors.size()) + " frames; the paper's pipeline with its " +
         "polynomial from the same markers " + fixed(mean(paper_errors), 1) + " cm over " +
         std::to_string(paper_errors.size()) + ".";
}

std::vector<ReportFigure> court_figures(const fs::path& dir,
                                        const std::vector<std::string>& files) {
  std::vector<ReportFigure> figures;
  for (const std::string& name : files) {
    if (!is_png(name)) continue;
    // court_NNNN_camK.png -> court_NNNN.json, camera K
    const std::string scene = name.substr(0, name.rfind("_cam"));
    const int camera = std::stoi(name.substr(name.rfind("_cam") + 4));
    const nlohmann::json truth = read_json(dir / (scene + ".json"));
    int balls = 0, visible = 0, references = 0;
    for (const auto& object : truth["objects"]) {
      const bool seen = object["views"][static_cast<size_t>(camera)]["visible"].get<bool>();
      if (object["kind"] == "tennis_ball") balls += 1, visible += seen;
      if (object["kind"] == "reference_ball") references += seen;
    }
    figures.push_back({"court/" + name, "camera " + std::to_string(camera) + ": " +
                                            std::to_string(visible) + " of " +
                                            std::to_string(balls) + " tennis balls visible, " +
                                            std::to_string(references) + " reference balls"});
  }
  return figures;
}

// The evaluation's table without its list of the pictures written (the report shows them).
std::string scores_only(const std::string& text) {
  std::istringstream in(text);
  std::string kept, line;
  while (std::getline(in, line)) {
    if (!line.starts_with("wrote ")) kept += line + "\n";
  }
  return kept;
}

}  // namespace

/// The closed loop's section: each run's map and latency chart, the table, what happened when.
std::string loop_section(const std::vector<LoopDemoRun>& runs, const fs::path& out_dir,
                         std::vector<ReportFigure>& figures) {
  std::string events;
  for (const LoopDemoRun& r : runs) {
    const std::string map = "loop/" + r.name + "/map.png";
    const std::string latency = "loop/" + r.name + "/latency.png";
    const std::string outcome =
        std::to_string(r.score.collected) + " of " + std::to_string(r.score.balls) + " balls" +
        (r.score.all ? " in " + fixed(r.score.time_s, 1) + " s" : " (not all)") + ", " +
        fixed(r.score.distance_m, 1) + " m driven";
    write_png_atomic(out_dir / map,
                     draw_loop_map(court_floor(sim::TennisCourtSpec{}), loop_map_input(r.truth),
                                   r.name + ": " + outcome));
    write_png_atomic(out_dir / latency,
                     draw_latency_chart(r.seqs, r.latency_ms,
                                        r.name + ": frames captured -> update at the robot"));
    figures.push_back({map,
                       "true path, routes as published, balls by the time they were "
                       "collected (grey, red cross: never); " +
                           outcome});
    figures.push_back({latency, "per-update latency at the robot (wall ms)"});
    for (const TruthEvent& e : r.events) {
      events += r.name + " at " + fixed(e.time_s, 1) + " s: " + e.what + "\n";
    }
  }
  return "<pre>" + loop_demo_table(runs) +
         "</pre><p>What happened, and when (simulated):</p><pre>" + events + "</pre>";
}

DemoResult run_demo(const DemoOptions& options, const fs::path& out_dir,
                    const LoopDemoRunner& run_loop,
                    const std::function<void(const std::string&)>& progress) {
  options.validate();
  ensure_directory(out_dir);

  const auto omni_start = Clock::now();
  sim::OmniScenarioOptions omni;
  omni.seed = options.seed;
  omni.frames = options.omni_frames;
  omni.effects.noise_sigma = 3.0;
  const std::vector<std::string> omni_files = sim::write_omni_dataset(omni, out_dir / "omni");
  const double omni_seconds = seconds_since(omni_start);

  const auto court_start = Clock::now();
  sim::CourtDatasetOptions court;
  court.seed = options.seed;
  court.scenes = options.court_scenes;
  const std::vector<std::string> court_files = sim::write_court_dataset(court, out_dir / "court");
  const double court_seconds = seconds_since(court_start);

  std::vector<ReportFigure> omni_figs = omni_figures(out_dir / "omni", omni_files);
  const std::string omni_results = omni_localisation(out_dir / "omni", omni_figs);
  const std::vector<ReportFigure> court_figs = court_figures(out_dir / "court", court_files);
  const std::string omni_intro =
      "On-board omnidirectional camera (misaligned as the omnivision paper's robot: tilted axis, "
      "offset mirror centre) on an 8 x 12 m MSL field; " +
      std::to_string(omni_figs.size()) + " frames rendered with their truth in " +
      fixed(omni_seconds, 2) + " s. Truth JSON beside each image (docs/sim-omni.md). " +
      omni_results;
  const std::string court_intro =
      "Tennis court with four corner cameras (1280x720, wide lenses); " +
      std::to_string(options.court_scenes) + " scene(s) rendered in " + fixed(court_seconds, 2) +
      " s, including each camera's one-off ray table. Truth JSON per scene (docs/sim-court.md).";
  const auto eval_start = Clock::now();
  CourtEvalOptions court_eval;
  court_eval.seed = options.seed;
  court_eval.scenes = options.court_scenes;
  court_eval.plot_dir = out_dir / "court-eval";
  court_eval.plot_scenes = options.court_scenes;
  const CourtEvalReport court_report = run_court_eval(court_eval);
  std::vector<ReportFigure> eval_figs;
  for (const std::string& picture : court_report.pictures) {
    eval_figs.push_back({"court-eval/" + fs::path(picture).filename().string(),
                         picture.find("field") != std::string::npos
                             ? "top-down field map, truth against each method's estimate"
                             : "one camera's view with each method's detections"});
  }
  const std::string eval_intro =
      "Both court methods calibrated from rendered chessboards and the reference balls (not "
      "given the truth), then run on " +
      std::to_string(options.court_scenes) +
      " simulated scene(s) of their own, scored against the truth in " +
      fixed(seconds_since(eval_start), 1) + " s (docs/court-eval.md):<pre>" +
      scores_only(court_eval_text(court_report)) + "</pre>";
  ensure_directory(out_dir / "plan");
  const std::vector<ReportFigure> plan_figs{
      {"plan/route-practice-50.png",
       "the report's rule (red), nearest neighbour (blue) and ballsight (green) on the court"}};
  const std::string plan_intro =
      "The order in which the robot collects 50 balls left after practice (along the baselines "
      "and at the foot of the net), round the net, turning costed (1 m/s, 90 deg/s), the 70 cm "
      "collector taking the balls it passes (docs/route-planning.md):<pre>" +
      eval::plan_comparison(eval::BallLayout::practice, 50, options.seed,
                            out_dir / plan_figs[0].image) +
      "</pre>";
  LoopDemoOptions loop;
  loop.seed = options.seed;
  loop.balls = options.loop_balls;
  loop.max_time_s = options.loop_max_time_s;
  loop.faults = options.loop_faults;
  const auto loop_start = Clock::now();
  const std::vector<LoopDemoRun> runs = run_loop(loop, out_dir, progress);
  std::vector<ReportFigure> loop_figs;
  const std::string loop_results = loop_section(runs, out_dir, loop_figs);
  const std::string loop_intro =
      "The closed loop: the navigation service on the simulated court (<code>ballsight serve "
      "--sim</code>: four cameras rendered every 0.1 s of simulated time from the truth, the "
      "pipeline, the planner) and the robot (<code>ballsight robot</code>: it knows only what the "
      "service sends) as two processes over loopback HTTP/WebSocket, " +
      std::to_string(options.loop_balls) +
      " balls, until all are collected, the robot sees none left, or " +
      fixed(options.loop_max_time_s, 0) +
      " s. Systems: the report's pipeline and priority rule (report), ballsight's pipeline with "
      "the priority rule (priority), ballsight; then ballsight with faults (a camera dies, the "
      "service and "
      "the robot are killed and started again). Scored on the court's record (contacts: ticks of "
      "0.1 s in which the net or the fence stopped the robot); " +
      fixed(seconds_since(loop_start), 1) + " s wall (docs/robot-link.md):" + loop_results;
  const std::string title = "ballsight demo (seed " + std::to_string(options.seed) + ")";

  const std::vector<ReportSection> sections{
      {"Omnidirectional rig", omni_intro, omni_figs},
      {"Court rig", court_intro, court_figs},
      {"Court: calibration, detection and world model", eval_intro, eval_figs},
      {"Court: collection route", plan_intro, plan_figs},
      {"Court: the closed loop", loop_intro, loop_figs}};

  DemoResult result{out_dir / "report.html", out_dir / "report.md",
                    static_cast<int>(omni_figs.size() + court_figs.size() + eval_figs.size() +
                                     plan_figs.size() + loop_figs.size())};
  write_file_atomic(result.report_html, html_report(title, sections));
  write_file_atomic(result.report_markdown, markdown_report(title, sections));
  return result;
}

}  // namespace ballsight
