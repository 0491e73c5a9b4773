#pragma once
// The wall-clock times of an evaluation, kept apart from its figures: with one seed, everything
// an evaluation prints in JSON but its "wall_clock" member is the same to the byte in every run
// (docs/RESULTS.md, "Same seed, same figures").

#include <nlohmann/json.hpp>
#include <set>
#include <string>

namespace ballsight {

/// `doc` with every object member named in `names`, at any depth, moved under doc["wall_clock"]
/// at the same path: {"methods": {"a": {"ms": 1, "recall": 1}}} with names {"ms"} becomes
/// {"methods": {"a": {"recall": 1}}, "wall_clock": {"methods": {"a": {"ms": 1}}}}. Arrays are
/// left as they are. "wall_clock" is always there (empty when nothing was timed).
nlohmann::json with_wall_clock_apart(nlohmann::json doc, const std::set<std::string>& names);

}  // namespace ballsight
