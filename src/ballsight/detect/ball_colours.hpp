#pragma once
// The colour model of a ball detector that knows nothing of the camera: a few named colours, each
// a strict hue band that seeds a ball and a looser one its blob grows through (the shaded side,
// the pale sunlit top, the mixed pixels of the rim). A two-coloured ball (a stage ball: orange
// with a yellow band) is one blob: every colour's growth band is one class.
//
// Saved as JSON: {"format": "ballsight-ball-colours", "version": 1, "colours": [{"name": ..,
// "seed": BAND, "grow": BAND, "far": true (optional)}]}, BAND = {"hue_deg": [min, max],
// "min_saturation": 0-1, "min_value": 0-255} (a hue band with min > max wraps through 0).

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ballsight/detect/color_classes.hpp"
#include "ballsight/detect/hue_classes.hpp"

namespace ballsight {

struct BallColour {
  std::string name;
  HueBand seed;  // a ball's blob holds at least one pixel of it
  HueBand grow;  // the blob grows through it
  /// Seeds far balls only: its seed counts in the seed share of circles of at most
  /// kFarBallMaxRadiusPx. The washed-out colour of a ball a few pixels wide (a JPEG's chroma at
  /// half resolution), which a larger ball keeps.
  bool far = false;
};

struct BallColours {
  std::vector<BallColour> colours;

  /// Throws InputError naming `where` and the first invalid colour or field.
  void validate(const std::string& where) const;
};

/// Tennis balls out of the box: optic yellow (hue 40-95 deg, its shade and sunlit top 30-110),
/// optic yellow in a hard shadow (darker, as saturated), the orange of stage balls (hue 5-40
/// deg) and a far stage ball's washed-out orange. The first three were chosen from the colours of
/// balls; the far orange's bands were set looking at the real labelled photos
/// (docs/detect-balls.md).
BallColours default_ball_colours();

/// The largest ball, in pixels of radius, whose seed a far colour is (BallColour::far): a ball of
/// 3-4 px whose pale top grows can be fitted with a circle of more than 4 px (docs/RESULTS.md).
inline constexpr double kFarBallMaxRadiusPx = 8.0;

/// Class bits of a ball colour table.
inline constexpr ColorClassMask kBallSeedClass = 1;
inline constexpr ColorClassMask kBallGrowClass = 2;     // set for seed colours too
inline constexpr ColorClassMask kFarBallSeedClass = 4;  // a far colour's seed (BallColour::far)

/// The table of every colour's seed and growth bands (a seed colour is always a growth colour).
ColorClassTable ball_colour_table(const BallColours& colours);

nlohmann::json ball_colours_json(const BallColours& colours);
/// Throws InputError naming `where` and the field at fault.
BallColours ball_colours_from_json(const nlohmann::json& json, const std::string& where);

/// Reads and validates a colour model file; errors name the file and the field.
BallColours read_ball_colours(const std::string& path);
/// Writes `colours` (validated first) to `path`.
void write_ball_colours(const std::string& path, const BallColours& colours);

}  // namespace ballsight
