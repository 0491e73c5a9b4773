#include "ballsight/detect/ball_colours.hpp"

#include <cmath>

#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/core/json_fields.hpp"

namespace ballsight {

namespace {

constexpr const char* kFormat = "ballsight-ball-colours";
constexpr int kVersion = 1;
constexpr std::size_t kMaxColours = 8;

// Hue distance travelled from `from` to `to` going up (through 360 when to < from).
double hue_span(double from, double to) {
  return to >= from ? to - from : to + 360.0 - from;
}

bool band_within(const HueBand& inner, const HueBand& outer) {
  const double outer_span = hue_span(outer.hue_min_deg, outer.hue_max_deg);
  return hue_span(outer.hue_min_deg, inner.hue_min_deg) <= outer_span &&
         hue_span(outer.hue_min_deg, inner.hue_max_deg) <= outer_span &&
         hue_span(outer.hue_min_deg, inner.hue_min_deg) <=
             hue_span(outer.hue_min_deg, inner.hue_max_deg) &&
         inner.min_saturation >= outer.min_saturation && inner.min_value >= outer.min_value &&
         inner.min_chroma >= outer.min_chroma;
}

nlohmann::json band_json(const HueBand& band) {
  return {{"hue_deg", {band.hue_min_deg, band.hue_max_deg}},
          {"min_saturation", band.min_saturation},
          {"min_value", band.min_value}};
}

HueBand band_from_json(const nlohmann::json& json, const std::string& where) {
  const std::vector<double> hue = json_numbers(json, "hue_deg", where, 2);
  HueBand band;
  band.hue_min_deg = hue[0];
  band.hue_max_deg = hue[1];
  band.min_saturation = json_number(json, "min_saturation", where);
  band.min_value = json_number(json, "min_value", where);
  band.validate(where.c_str());
  return band;
}

}  // namespace

void BallColours::validate(const std::string& where) const {
  require(!colours.empty() && colours.size() <= kMaxColours, where + ".colours",
          "need 1 to " + std::to_string(kMaxColours) + " colours");
  for (std::size_t i = 0; i < colours.size(); ++i) {
    const std::string at = where + ".colours[" + std::to_string(i) + "]";
    colours[i].seed.validate((at + ".seed").c_str());
    colours[i].grow.validate((at + ".grow").c_str());
    require(band_within(colours[i].seed, colours[i].grow), at,
            "the seed band must lie within the grow band (hue, saturation and value)");
  }
}

BallColours default_ball_colours() {
  BallColours model;
  const HueBand yellow_growth{30.0, 110.0, 0.0, 0.22, 30.0};
  model.colours.push_back({"optic yellow", HueBand{40.0, 95.0, 0.0, 0.35, 70.0}, yellow_growth});
  // In a hard shadow the felt, lit by the sky alone, keeps its hue and most of its saturation
  // while its value falls below the sunlit band; dark foliage is much less saturated.
  model.colours.push_back(
      {"optic yellow in shade", HueBand{45.0, 85.0, 0.0, 0.7, 40.0}, yellow_growth});
  model.colours.push_back(
      {"stage orange", HueBand{5.0, 40.0, 0.0, 0.55, 90.0}, HueBand{0.0, 50.0, 0.0, 0.35, 40.0}});
  // A far orange ball (2-3 px radius) in a JPEG has its chroma averaged with the floor's by the
  // 4:2:0 subsampling: its core keeps the red-orange hue at 0.4-0.7 saturation, its sunlit top
  // 0.15-0.3. Only bright red-orange is let down so far: dry leaves, cardboard and wood lie at
  // 25-40 deg with that saturation, a red court's paint below 5 deg, and a warm-lit line is dim.
  model.colours.push_back({"stage orange, far", HueBand{5.0, 20.0, 0.0, 0.45, 100.0},
                           HueBand{5.0, 22.0, 0.0, 0.2, 100.0}, true});
  return model;
}

ColorClassTable ball_colour_table(const BallColours& colours) {
  colours.validate("ball colours");
  std::vector<HueClassRule> rules;
  for (const BallColour& colour : colours.colours) {
    rules.push_back({static_cast<ColorClassMask>((colour.far ? kFarBallSeedClass : kBallSeedClass) |
                                                 kBallGrowClass),
                     colour.seed});
    rules.push_back({kBallGrowClass, colour.grow});
  }
  return hue_class_table(rules);
}

nlohmann::json ball_colours_json(const BallColours& colours) {
  nlohmann::json list = nlohmann::json::array();
  for (const BallColour& colour : colours.colours) {
    nlohmann::json item = {
        {"name", colour.name}, {"seed", band_json(colour.seed)}, {"grow", band_json(colour.grow)}};
    if (colour.far) item["far"] = true;
    list.push_back(item);
  }
  return {{"format", kFormat}, {"version", kVersion}, {"colours", list}};
}

BallColours ball_colours_from_json(const nlohmann::json& json, const std::string& where) {
  json_require_string(json, "format", where, kFormat);
  json_int(json, "version", where, kVersion, kVersion);
  const nlohmann::json& list = json_member(json, "colours", where);
  require(list.is_array(), where + ".colours", "expected an array");
  BallColours colours;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string at = where + ".colours[" + std::to_string(i) + "]";
    BallColour colour;
    colour.name = json_string(list[i], "name", at);
    colour.seed = band_from_json(json_member(list[i], "seed", at), at + ".seed");
    colour.grow = band_from_json(json_member(list[i], "grow", at), at + ".grow");
    if (list[i].contains("far")) colour.far = json_bool(list[i], "far", at);
    colours.colours.push_back(colour);
  }
  colours.validate(where);
  return colours;
}

BallColours read_ball_colours(const std::string& path) {
  return ball_colours_from_json(read_json_document(path), path);
}

void write_ball_colours(const std::string& path, const BallColours& colours) {
  colours.validate(path);
  write_file_atomic(path, ball_colours_json(colours).dump(2) + "\n");
}

}  // namespace ballsight
