#include "ballsight/detect/photo_ball_fit.hpp"

#include <algorithm>
#include <functional>

#include "ballsight/camera/image_file.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/json_fields.hpp"

namespace ballsight {

namespace {

constexpr const char* kDetectorFormat = "ballsight-photo-ball-detector";

constexpr const char* kShippedJson =
#include "shipped_photo_ball_detector.inc"
    ;

// What the search tries: one number of the settings and the grid of its values.
struct Knob {
  const char* name;
  std::vector<double> values;
  std::function<void(PhotoBallOptions&, double)> set;
};

// The optic yellow's seed band (colour 0 of default_ball_colours) and the growth band it shares
// with the yellow in shade (colour 1).
HueBand& yellow_seed(PhotoBallOptions& o) {
  return o.colours.colours.at(0).seed;
}
void set_yellow_growth(PhotoBallOptions& o, const std::function<void(HueBand&)>& change) {
  change(o.colours.colours.at(0).grow);
  change(o.colours.colours.at(1).grow);
}

std::vector<Knob> knobs() {
  return {
      {"min_score",
       {0.2, 0.25, 0.3, 0.35, 0.4, 0.45, 0.5, 0.55},
       [](PhotoBallOptions& o, double v) { o.circles.min_score = v; }},
      {"yellow seed min_saturation",
       {0.15, 0.2, 0.25, 0.3, 0.35, 0.4, 0.45},
       [](PhotoBallOptions& o, double v) { yellow_seed(o).min_saturation = v; }},
      {"yellow seed min_value",
       {40, 55, 70, 85, 100, 130},
       [](PhotoBallOptions& o, double v) { yellow_seed(o).min_value = v; }},
      {"yellow seed hue_min",
       {30, 35, 40, 45, 50},
       [](PhotoBallOptions& o, double v) { yellow_seed(o).hue_min_deg = v; }},
      {"yellow seed hue_max",
       {75, 80, 85, 90, 95, 100, 110},
       [](PhotoBallOptions& o, double v) { yellow_seed(o).hue_max_deg = v; }},
      {"yellow growth min_saturation",
       {0.08, 0.12, 0.16, 0.22, 0.28},
       [](PhotoBallOptions& o, double v) {
         set_yellow_growth(o, [v](HueBand& b) { b.min_saturation = v; });
       }},
      {"yellow growth hue_max",
       {85, 95, 110, 125},
       [](PhotoBallOptions& o, double v) {
         set_yellow_growth(o, [v](HueBand& b) { b.hue_max_deg = v; });
       }},
      {"split min_contrast",
       {20, 30, 40, 50, 60, 80, 255},
       [](PhotoBallOptions& o, double v) { o.split.min_contrast = v; }},
      {"split max_share",
       {0.15, 0.2, 0.3, 0.4, 0.5},
       [](PhotoBallOptions& o, double v) { o.split.max_share = v; }},
      {"yellow growth min_value",
       {15, 30, 50},
       [](PhotoBallOptions& o, double v) {
         set_yellow_growth(o, [v](HueBand& b) { b.min_value = v; });
       }},
  };
}

bool valid(const PhotoBallOptions& options) {
  try {
    options.validate();
    return true;
  } catch (const InputError&) {
    return false;
  }
}

double mean_f1(const PhotoBallOptions& options, std::span<const LabelledPhotos> sources) {
  PhotoBallDetector detector(options);
  double sum = 0.0;
  for (const LabelledPhotos& photos : sources) sum += f1_score(score_photos(detector, photos));
  return sum / static_cast<double>(sources.size());
}

}  // namespace

LabelledPhotos read_labelled_photos(const LabelledSource& source) {
  LabelledPhotos photos{source.name, {}, {}, {}, {}};
  for (const LabelledImage& image : source.images) {
    photos.files.push_back(image.file);
    photos.images.push_back(read_image_bgr(source.images_dir / image.file));
    photos.labels.push_back(image.balls);
  }
  return photos;
}

PhotoSources read_photo_sources(const std::filesystem::path& root,
                                std::span<const std::string> names, const std::string& option) {
  PhotoSources out;
  for (const LabelledSource& source : read_labelled_sources(root)) {
    const bool named = std::find(names.begin(), names.end(), source.name) != names.end();
    (named ? out.named : out.others).push_back(read_labelled_photos(source));
  }
  for (const std::string& name : names) {
    require(std::any_of(out.named.begin(), out.named.end(),
                        [&](const LabelledPhotos& p) { return p.source == name; }),
            option, name + " is no source of " + root.string());
  }
  return out;
}

BallMatch score_photos(PhotoBallDetector& detector, const LabelledPhotos& photos) {
  return score_photos(photos, [&](std::size_t k) { return detector.detect(photos.images[k]); });
}

BallMatch score_photos(const LabelledPhotos& photos,
                       const std::function<std::vector<PhotoBall>(std::size_t)>& balls_of) {
  BallMatch total;
  for (std::size_t k = 0; k < photos.images.size(); ++k) {
    const std::vector<PhotoBall> balls =
        without_ignored(balls_of(k), photos.labels[k], photos.ignored_in(k));
    add_match(total, match_balls_to_labels(photos.labels[k], balls, photos.images[k].size()));
  }
  return total;
}

void PhotoBallFitOptions::validate() const {
  start.validate();
  require(start.colours.colours.size() >= 2, "start.colours",
          "needs the optic yellow and its shade first (default_ball_colours)");
  require(rounds >= 1 && rounds <= 10, "rounds", "must be within [1, 10]");
}

PhotoBallOptions shipped_photo_ball_options() {
  static const PhotoBallOptions shipped = photo_ball_options_from_json(
      nlohmann::json::parse(kShippedJson), "detect/shipped_photo_ball_detector.json");
  return shipped;
}

PhotoBallFit fit_photo_ball_detector(std::span<const LabelledPhotos> sources,
                                     const PhotoBallFitOptions& options) {
  options.validate();
  require(!sources.empty(), "fit", "needs at least one labelled source");
  PhotoBallFit fit{options.start, {}, mean_f1(options.start, sources), 1};
  for (const LabelledPhotos& photos : sources) fit.fitted_on.push_back(photos.source);
  for (int round = 0; round < options.rounds; ++round) {
    bool changed = false;
    for (const Knob& knob : knobs())
      for (const double value : knob.values) {
        PhotoBallOptions candidate = fit.options;
        knob.set(candidate, value);
        if (!valid(candidate)) continue;
        const double f1 = mean_f1(candidate, sources);
        ++fit.evaluations;
        if (f1 > fit.mean_f1 + 1e-9) fit.options = candidate, fit.mean_f1 = f1, changed = true;
      }
    if (!changed) break;
  }
  return fit;
}

nlohmann::json photo_ball_fit_json(const PhotoBallFit& fit) {
  return {{"format", kDetectorFormat},
          {"version", 1},
          {"colours", ball_colours_json(fit.options.colours)},
          {"min_score", fit.options.circles.min_score},
          {"split",
           {{"min_contrast", fit.options.split.min_contrast},
            {"max_share", fit.options.split.max_share}}},
          {"fitted_on", fit.fitted_on},
          {"mean_f1", fit.mean_f1}};
}

PhotoBallOptions photo_ball_options_from_json(const nlohmann::json& json,
                                              const std::string& where) {
  json_require_string(json, "format", where, kDetectorFormat);
  json_int(json, "version", where, 1, 1);
  PhotoBallOptions options;
  options.colours = ball_colours_from_json(json_member(json, "colours", where), where + ".colours");
  options.circles.min_score = json_number(json, "min_score", where);
  const nlohmann::json& split = json_member(json, "split", where);
  options.split.min_contrast = json_number(split, "min_contrast", where + ".split");
  options.split.max_share = json_number(split, "max_share", where + ".split");
  try {
    options.validate();
  } catch (const InputError& e) {
    throw InputError(where + ": " + e.what());
  }
  return options;
}

PhotoBallOptions read_photo_ball_options(const std::string& path) {
  return photo_ball_options_from_json(read_json_document(path), path);
}

}  // namespace ballsight
