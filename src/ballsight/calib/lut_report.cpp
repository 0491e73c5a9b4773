// Text and JSON reports of a lookup table inspection (declared in lut_inspect.hpp).

#include <cstdio>
#include <sstream>

#include "ballsight/calib/lut_inspect.hpp"

namespace ballsight {

namespace {

nlohmann::ordered_json optional_number(const std::optional<double>& v) {
  return v ? nlohmann::ordered_json(*v) : nlohmann::ordered_json(nullptr);
}

std::string fixed(const std::optional<double>& v, int decimals = 1) {
  if (!v) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", decimals, *v);
  return text;
}

double hole_fraction(const LutInspection& in) {
  return in.written_bins > 0 ? static_cast<double>(in.holes) / static_cast<double>(in.written_bins)
                             : 0.0;
}

}  // namespace

nlohmann::ordered_json to_json(const LutInspection& in) {
  nlohmann::ordered_json spread = nlohmann::ordered_json::array();
  for (const RadiusSpread& s : in.spread) {
    spread.push_back({{"radius_px", s.radius_px},
                      {"directions", s.directions},
                      {"min_cm", s.min_cm},
                      {"max_cm", s.max_cm},
                      {"spread_cm", s.spread_cm()}});
  }
  return {
      {"source", in.source},
      {"format", in.format},
      {"directions", in.rays.size()},
      {"bins", in.bins},
      {"radius_step_px", in.radius_step_px},
      {"written_directions", in.written_directions},
      {"first_written_px",
       {{"min", optional_number(in.first_written_min_px)},
        {"median", optional_number(in.first_written_median_px)},
        {"max", optional_number(in.first_written_max_px)}}},
      {"last_written_px",
       {{"min", optional_number(in.last_written_min_px)},
        {"max", optional_number(in.last_written_max_px)}}},
      {"monotonic_until_px", optional_number(in.monotonic_until_px)},
      {"monotonic_until_theta_deg", in.monotonic_until_theta_deg},
      {"non_monotonic_directions", in.non_monotonic_directions},
      {"drop_tolerance_cm", in.drop_tolerance_cm},
      {"spread", spread},
      {"holes",
       {{"count", in.holes},
        {"fraction", hole_fraction(in)},
        {"directions", in.directions_with_holes}}},
  };
}

std::string format_report(const LutInspection& in) {
  std::ostringstream out;
  const auto line = [&out](const std::string& key, const std::string& value) {
    char padded[32];
    std::snprintf(padded, sizeof padded, "%-27s", key.c_str());
    out << padded << value << "\n";
  };
  line("source", in.source);
  line("format", in.format);
  line("directions", std::to_string(in.rays.size()));
  line("bins", std::to_string(in.bins));
  line("radius_step_px", fixed(in.radius_step_px));
  line("written_directions", std::to_string(in.written_directions));
  line("first_written_px", "min " + fixed(in.first_written_min_px) + "  median " +
                               fixed(in.first_written_median_px) + "  max " +
                               fixed(in.first_written_max_px));
  line("last_written_px",
       "min " + fixed(in.last_written_min_px) + "  max " + fixed(in.last_written_max_px));
  line("monotonic_until_px", fixed(in.monotonic_until_px));
  line("monotonic_until_theta_deg", std::to_string(in.monotonic_until_theta_deg));
  line("non_monotonic_directions", std::to_string(in.non_monotonic_directions));
  line("drop_tolerance_cm", fixed(in.drop_tolerance_cm));
  if (in.spread.empty()) line("spread", "-");
  for (std::size_t i = 0; i < in.spread.size(); ++i) {
    const RadiusSpread& s = in.spread[i];
    line(i == 0 ? "spread" : "", "at " + fixed(s.radius_px, 0) + " px: " + fixed(s.min_cm, 0) +
                                     " .. " + fixed(s.max_cm, 0) +
                                     " cm = " + fixed(s.spread_cm(), 0) + " cm over " +
                                     std::to_string(s.directions) + " directions");
  }
  line("holes", "count " + std::to_string(in.holes) + "  fraction " + fixed(hole_fraction(in), 5) +
                    "  directions " + std::to_string(in.directions_with_holes));
  return out.str();
}

}  // namespace ballsight
