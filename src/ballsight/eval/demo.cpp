#include "ballsight/eval/demo.hpp"

#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/sim/court_dataset.hpp"
#include "ballsight/sim/omni_dataset.hpp"

namespace ballsight {

namespace fs = std::filesystem;

void DemoOptions::validate() const {
  require(omni_frames >= 1 && omni_frames <= 100, "demo", "omni_frames must be 1..100");
  require(court_scenes >= 1 && court_scenes <= 20, "demo", "court_scenes must be 1..20");
}

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
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

// One report row per image: the picture and what the truth says it shows.
struct Figure {
  std::string image;  // relative to the report
  std::string caption;
};

std::vector<Figure> omni_figures(const fs::path& dir, const std::vector<std::string>& files) {
  std::vector<Figure> figures;
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

std::vector<Figure> court_figures(const fs::path& dir, const std::vector<std::string>& files) {
  std::vector<Figure> figures;
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

std::string html_section(const std::string& title, const std::string& intro,
                         const std::vector<Figure>& figures) {
  std::ostringstream html;
  html << "<h2>" << title << "</h2>\n<p>" << intro << "</p>\n<div class=\"grid\">\n";
  for (const Figure& f : figures) {
    html << "<figure><a href=\"" << f.image << "\"><img src=\"" << f.image << "\" alt=\"" << f.image
         << "\"></a><figcaption>" << f.image << ": " << f.caption << "</figcaption></figure>\n";
  }
  html << "</div>\n";
  return html.str();
}

std::string markdown_section(const std::string& title, const std::string& intro,
                             const std::vector<Figure>& figures) {
  std::ostringstream md;
  md << "## " << title << "\n\n" << intro << "\n\n";
  for (const Figure& f : figures) md << "- `" << f.image << "`: " << f.caption << "\n";
  md << "\n";
  return md.str();
}

}  // namespace

DemoResult run_demo(const DemoOptions& options, const fs::path& out_dir) {
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

  const std::vector<Figure> omni_figs = omni_figures(out_dir / "omni", omni_files);
  const std::vector<Figure> court_figs = court_figures(out_dir / "court", court_files);
  const std::string omni_intro =
      "On-board omnidirectional camera (misaligned as the omnivision paper's robot: tilted axis, "
      "offset mirror centre) on an 8 x 12 m MSL field; " +
      std::to_string(omni_figs.size()) + " frames rendered with their truth in " +
      fixed(omni_seconds, 2) + " s. Truth JSON beside each image (docs/sim-omni.md).";
  const std::string court_intro =
      "Tennis court with four corner cameras (1280x720, wide lenses); " +
      std::to_string(options.court_scenes) + " scene(s) rendered in " + fixed(court_seconds, 2) +
      " s, including each camera's one-off ray table. Truth JSON per scene (docs/sim-court.md).";
  const std::string title = "ballsight demo (seed " + std::to_string(options.seed) + ")";

  std::ostringstream html;
  html << "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" << title
       << "</title>\n<style>body{font-family:sans-serif;max-width:1400px;margin:2em auto;}"
          ".grid{display:grid;grid-template-columns:repeat(auto-fill,minmax(320px,1fr));gap:1em}"
          "img{width:100%;border:1px solid #ccc}figcaption{font-size:0.85em}</style></head>"
          "<body>\n<h1>"
       << title << "</h1>\n"
       << html_section("Omnidirectional rig", omni_intro, omni_figs)
       << html_section("Court rig", court_intro, court_figs) << "</body></html>\n";
  const std::string markdown = "# " + title + "\n\n" +
                               markdown_section("Omnidirectional rig", omni_intro, omni_figs) +
                               markdown_section("Court rig", court_intro, court_figs);

  DemoResult result{out_dir / "report.html", out_dir / "report.md",
                    static_cast<int>(omni_figs.size() + court_figs.size())};
  write_file_atomic(result.report_html, html.str());
  write_file_atomic(result.report_markdown, markdown);
  return result;
}

}  // namespace ballsight
