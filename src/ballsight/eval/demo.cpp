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
#include "ballsight/eval/loop_replay_data.hpp"
#include "ballsight/eval/plan_eval.hpp"
#include "ballsight/eval/plot_inputs.hpp"
#include "ballsight/pipeline/marker_frame_samples.hpp"
#include "ballsight/pipeline/omni_pipelines.hpp"
#include "ballsight/pipeline/world_model_json.hpp"
#include "ballsight/service/simulated_court.hpp"
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
// robots), against the truth. Appends to the frames' captions; returns the summary and puts the
// errors in `table`.
std::string omni_localisation(const fs::path& dir, std::vector<ReportFigure>& figures,
                              ReportTable& table) {
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
  table = {
      "The ball placed on the floor in every frame after the first, against the truth",
      {"pipeline", "mean ball error (cm)", "frames"},
      {{"ballsight", fixed(mean(ballsight_errors), 2), std::to_string(ballsight_errors.size())},
       {"the paper's (its polynomial, from the same markers)", fixed(mean(paper_errors), 1),
        std::to_string(paper_errors.size())}}};
  return "Calibrated without clicking: " + std::to_string(found.samples.size()) + " of " +
         std::to_string(layout.size()) + " markers found in frame 0 and matched to the paper's " +
         "layout, ballsight's model fitted and baked into omni/ballsight.bsgm in " +
         fixed(calibration_seconds, 2) + " s (docs/omni-calibration.md).";
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

// The evaluation's scores, a row per method.
ReportTable court_eval_table(const CourtEvalReport& report) {
  ReportTable table{"Scored against the truth (match radius " +
                        fixed(100.0 * report.options.match_radius_m, 0) +
                        " cm; the robot's errors over the scenes where it was found)",
                    {"method", "recall", "precision", "duplicates", "false positives",
                     "ball error mean / p95 (cm)", "robot position (cm)", "robot heading (deg)",
                     "robot found", "ms per frame set"},
                    {}};
  for (const MethodReport& m : report.methods) {
    const std::string name(court_method_name(m.method));
    if (!m.calibration_error.empty()) {
      table.rows.push_back({name, "could not be calibrated: " + m.calibration_error});
      continue;
    }
    const CourtScores& s = m.scores;
    double ms = 0.0;
    for (double v : m.frame_set_ms) ms += v / static_cast<double>(m.frame_set_ms.size());
    table.rows.push_back(
        {name, fixed(100.0 * s.recall(), 2) + " %", fixed(100.0 * s.precision(), 2) + " %",
         std::to_string(s.duplicates), std::to_string(s.false_positives),
         fixed(100.0 * s.ball_error_mean_m(), 2) + " / " + fixed(100.0 * s.ball_error_p95_m(), 2),
         fixed(100.0 * s.robot_position_error_mean_m(), 2),
         fixed(deg_from_rad(s.robot_heading_error_mean_rad()), 3),
         std::to_string(s.robot_found) + " of " + std::to_string(s.scenes), fixed(ms, 1)});
  }
  return table;
}

/// The closed loop's figures (each run's map and latency chart), what happened when, the
/// recordings; appends the figures.
std::string loop_details(const std::vector<LoopDemoRun>& runs, const fs::path& out_dir,
                         std::vector<ReportFigure>& figures) {
  std::string events, recordings;
  for (const LoopDemoRun& r : runs) {
    for (const fs::path& file : r.recordings) {
      const std::string link = html_escaped(fs::relative(file, out_dir).generic_string());
      recordings +=
          "<li><a href=\"" + link + "\">" + link + "</a> (" + html_escaped(r.name) + ")</li>";
    }
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
    figures.push_back({map, r.name +
                                ": true path, routes as published, balls by the time they were "
                                "collected (grey, red cross: never); " +
                                outcome});
    figures.push_back({latency, r.name + ": per-update latency at the robot (wall ms)"});
    for (const TruthEvent& e : r.events) {
      events += r.name + " at " + fixed(e.time_s, 1) + " s: " + e.what + "\n";
    }
  }
  return "<p>What happened, and when (simulated):</p><pre>" + events +
         "</pre><p>Each run as recorded by its service (MCAP: every update, the frames once a "
         "second; a service that was killed left its file cut short, readable up to its last "
         "complete chunk). Open one in Foxglove or Lichtblick (File &gt; Open local file) for "
         "the court in 3D with a time slider, or read it with <code>ballsight record info "
         "FILE</code>; docs/recording.md.</p><ul>" +
         recordings + "</ul>";
}

// The page's replay of the closed loop (web/loop_replay.js on web/court_map.js): its controls,
// its data, and the script, or a note when the web pages' folder is not at hand.
struct LoopReplay {
  std::string html;
  std::string script;
};

LoopReplay loop_replay(const std::vector<LoopDemoRun>& runs, const fs::path& web_dir) {
  const fs::path map_js = web_dir / "court_map.js", replay_js = web_dir / "loop_replay.js";
  if (web_dir.empty() || !fs::exists(map_js) || !fs::exists(replay_js)) {
    return {"<p>(The replay needs the web pages' folder, which was not found: " +
                html_escaped(web_dir.string()) + ".)</p>",
            ""};
  }
  nlohmann::json data{{"site",
                       {{"court", site_court_json(site_court(sim::TennisCourtSpec{}))},
                        {"ball_radius_m", sim::kTennisBallRadiusM}}},
                      {"runs", nlohmann::json::array()}};
  for (const LoopDemoRun& r : runs) {
    nlohmann::json run = loop_replay_json(r.truth);
    run["name"] = r.name;
    data["runs"].push_back(std::move(run));
  }
  std::string json = data.dump();
  // Inside a <script> element "</" or "<!--" would upset it: every "<" as its JSON escape.
  for (std::size_t at = json.find('<'); at != std::string::npos; at = json.find('<', at + 6))
    json.replace(at, 1, "\\u003c");
  const std::string html =
      "<div class=\"replay\" id=\"loop-replay\"><div class=\"controls\"><label>Run "
      "<select></select></label><button type=\"button\">Play</button><input type=\"range\" "
      "min=\"0\" value=\"0\" aria-label=\"time\"><output></output></div><canvas "
      "width=\"1000\" height=\"520\"></canvas></div>\n<script type=\"application/json\" "
      "id=\"loop-replay-data\">" +
      json + "</script>\n";
  // A page opened from its folder may not import modules (file:// has no origin): the two
  // modules are inlined into one, their import and export keywords dropped.
  const auto module_text = [](const fs::path& file) {
    std::istringstream in(read_file(file));
    std::string text, line;
    while (std::getline(in, line)) {
      if (line.starts_with("import ")) continue;
      if (line.starts_with("export ")) line.erase(0, 7);
      text += line + "\n";
    }
    return text;
  };
  const std::string script =
      module_text(map_js) + module_text(replay_js) +
      "const data = JSON.parse(document.getElementById(\"loop-replay-data\").textContent);\n"
      "startLoopReplay(document.getElementById(\"loop-replay\"), data.site, data.runs);\n";
  return {html, script};
}

}  // namespace

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
  ReportTable omni_table;
  const std::string omni_results = omni_localisation(out_dir / "omni", omni_figs, omni_table);
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
      fixed(seconds_since(eval_start), 1) + " s (docs/court-eval.md).";
  ensure_directory(out_dir / "plan");
  const std::vector<ReportFigure> plan_figs{
      {"plan/route-practice-50.png",
       "the report's rule (red), nearest neighbour (blue) and ballsight (green) on the court"}};
  const std::string plan_intro =
      "The order in which the robot collects 50 balls left after practice (along the baselines "
      "and at the foot of the net), round the net, turning costed (1 m/s, 90 deg/s), the 70 cm "
      "collector taking the balls it passes (docs/route-planning.md).";
  const ReportTable plan_table = eval::plan_comparison(eval::BallLayout::practice, 50, options.seed,
                                                       out_dir / plan_figs[0].image);
  LoopDemoOptions loop;
  loop.seed = options.seed;
  loop.balls = options.loop_balls;
  loop.max_time_s = options.loop_max_time_s;
  loop.faults = options.loop_faults;
  const auto loop_start = Clock::now();
  const std::vector<LoopDemoRun> runs = run_loop(loop, out_dir, progress);
  std::vector<ReportFigure> loop_figs;
  const std::string loop_more = loop_details(runs, out_dir, loop_figs);
  const LoopReplay replay = loop_replay(runs, options.web_dir);
  const std::string loop_intro =
      "The closed loop: the navigation service on the simulated court (<code>ballsight serve "
      "--sim</code>: four cameras rendered every 0.1 s of simulated time from the truth, the "
      "pipeline, the planner) and the robot (<code>ballsight robot</code>: it knows only what the "
      "service sends) as two processes over loopback HTTP/WebSocket, " +
      std::to_string(options.loop_balls) +
      " balls, until all are collected, the robot sees none left, or " +
      fixed(options.loop_max_time_s, 0) +
      " s. Systems: the report's pipeline and priority rule (report), ballsight's pipeline with "
      "the priority rule (priority), ballsight" +
      (options.loop_faults ? "; then ballsight with faults (a camera dies, the service and the "
                             "robot are killed and started again)"
                           : "") +
      ". Scored on the court's record (contacts: ticks of 0.1 s in which the net or the fence "
      "stopped the robot); " +
      fixed(seconds_since(loop_start), 1) + " s wall (docs/robot-link.md). Below, the loop " +
      "replayed: pick a run, move the slider or play; the robot moves along its true path, " +
      "each ball goes when it was collected, and the route is the one the robot had then.";

  ReportPage page;
  page.title = "ballsight demo (seed " + std::to_string(options.seed) + ")";
  // The result first: every ball collected or not, how fast, against the report's system, with
  // ballsight's run on the court.
  page.result.title = "The result";
  page.result.intro =
      "The collecting robot on the simulated court, " + std::to_string(options.loop_balls) +
      " tennis balls, closed loop (the service and the robot as two processes): the report's "
      "whole system (report), ballsight's pipeline with the report's route rule (priority) and "
      "ballsight" +
      (options.loop_faults ? ", and ballsight again through a camera failure and both processes "
                             "killed and started again (ballsight-faults)."
                           : ".");
  page.result.tables = {loop_result_table(runs)};
  for (const ReportFigure& f : loop_figs) {
    if (f.image == "loop/ballsight/map.png") page.result.figures = {f};
  }
  page.sections = {{"Omnidirectional rig", omni_intro, "", {omni_table}, omni_figs, ""},
                   {"Court rig", court_intro, "", {}, court_figs, ""},
                   {"Court: calibration, detection and world model",
                    eval_intro,
                    "",
                    {court_eval_table(court_report)},
                    eval_figs,
                    ""},
                   {"Court: collection route", plan_intro, "", {plan_table}, plan_figs, ""},
                   {"Court: the closed loop",
                    loop_intro,
                    replay.html,
                    {loop_demo_table(runs)},
                    loop_figs,
                    loop_more}};
  page.script = replay.script;
  const std::string style_file = (options.web_dir / "style.css").string();
  if (!options.web_dir.empty() && fs::exists(style_file)) page.style = read_file(style_file);

  DemoResult result{out_dir / "report.html", out_dir / "report.md",
                    static_cast<int>(omni_figs.size() + court_figs.size() + eval_figs.size() +
                                     plan_figs.size() + loop_figs.size())};
  write_file_atomic(result.report_html, html_report(page));
  write_file_atomic(result.report_markdown, markdown_report(page));
  return result;
}

}  // namespace ballsight
