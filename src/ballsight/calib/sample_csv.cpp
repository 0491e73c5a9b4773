#include "ballsight/calib/sample_csv.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <optional>

#include "ballsight/core/csv_fields.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"

namespace ballsight {

namespace {

struct ColumnSpec {
  std::string_view name;
  bool required;
  double min;
  double max;
  bool min_inclusive;
  std::string_view expected;  // what a valid value looks like, for messages
};

// Columns in canonical order; the values' index is the column's id below.
constexpr std::array<ColumnSpec, 4> kColumns = {{
    {"theta_deg", true, 0.0, 360.0, true, "an angle in [0, 360) deg"},
    {"radius_px", true, 0.0, 1e5, false, "a radius in (0, 100000) px"},
    {"distance_cm", true, 0.0, 1e6, false, "a distance in (0, 1000000) cm"},
    {"bearing_deg", false, 0.0, 360.0, true, "an angle in [0, 360) deg"},
}};
constexpr std::size_t kTheta = 0, kRadius = 1, kDistance = 2, kBearing = 3;

using Field = CsvField;

class Located {
 public:
  Located(const std::string& source, std::size_t line) : source_(source), line_(line) {}
  [[noreturn]] void fail(std::size_t column, const std::string& what) const {
    throw InputError(source_ + ":" + std::to_string(line_) + ":" + std::to_string(column) + ": " +
                     what);
  }

 private:
  const std::string& source_;
  std::size_t line_;
};

std::string expected_header() {
  return "expected the header theta_deg,radius_px,distance_cm with optional bearing_deg";
}

// Header -> for each field, the id of its column.
std::vector<std::size_t> parse_header(std::string_view line, const Located& at) {
  std::vector<std::size_t> ids;
  std::array<bool, kColumns.size()> seen{};
  for (const Field& field : split_csv_fields(line)) {
    std::size_t id = 0;
    while (id < kColumns.size() && kColumns[id].name != field.text) ++id;
    if (id == kColumns.size()) {
      at.fail(field.column,
              "unknown column '" + std::string(field.text) + "'; " + expected_header());
    }
    if (seen[id]) at.fail(field.column, "duplicate column " + std::string(field.text));
    seen[id] = true;
    ids.push_back(id);
  }
  for (std::size_t id = 0; id < kColumns.size(); ++id) {
    if (kColumns[id].required && !seen[id]) {
      at.fail(1,
              "header lacks column " + std::string(kColumns[id].name) + "; " + expected_header());
    }
  }
  return ids;
}

double parse_value(const Field& field, const ColumnSpec& spec, const Located& at) {
  std::string_view text = field.text;
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  const std::string got = "got '" + std::string(field.text) + "'";
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() ||
      !std::isfinite(value)) {
    at.fail(field.column, std::string(spec.name) + ": expected a finite number, " + got);
  }
  const bool above_min = spec.min_inclusive ? value >= spec.min : value > spec.min;
  if (!above_min || value >= spec.max) {
    at.fail(field.column,
            std::string(spec.name) + ": expected " + std::string(spec.expected) + ", " + got);
  }
  return value;
}

PolarSample parse_row(std::string_view line, const std::vector<std::size_t>& ids,
                      const Located& at) {
  const std::vector<Field> fields = split_csv_fields(line);
  if (fields.size() > ids.size()) {
    at.fail(fields[ids.size()].column, "extra column " + std::to_string(ids.size() + 1) +
                                           ": the header has " + std::to_string(ids.size()) +
                                           " columns");
  }
  if (fields.size() < ids.size()) {
    at.fail(line.size() + 1, "missing column " + std::string(kColumns[ids[fields.size()]].name) +
                                 ": the header has " + std::to_string(ids.size()) + " columns");
  }
  PolarSample sample;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const ColumnSpec& spec = kColumns[ids[i]];
    if (!spec.required && fields[i].text.empty()) continue;  // optional value left out
    const double value = parse_value(fields[i], spec, at);
    switch (ids[i]) {
      case kTheta:
        sample.theta_deg = value;
        break;
      case kRadius:
        sample.radius_px = value;
        break;
      case kDistance:
        sample.distance_cm = value;
        break;
      case kBearing:
        sample.bearing_deg = value;
        break;
      default:
        break;
    }
  }
  return sample;
}

}  // namespace

std::vector<PolarSample> parse_polar_samples_csv(std::string_view text, const std::string& source) {
  constexpr std::string_view kBom = "\xEF\xBB\xBF";
  if (text.starts_with(kBom)) text.remove_prefix(kBom.size());
  std::optional<std::vector<std::size_t>> ids;
  std::vector<PolarSample> samples;
  std::size_t line_number = 0;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++line_number;
    if (line.ends_with('\r')) line.remove_suffix(1);
    if (trim_blanks(line).empty()) continue;
    const Located at(source, line_number);
    if (!ids) {
      ids = parse_header(line, at);
    } else {
      samples.push_back(parse_row(line, *ids, at));
    }
  }
  if (!ids) Located(source, 1).fail(1, "empty file; " + expected_header());
  if (samples.empty()) Located(source, line_number + 1).fail(1, "no sample rows after the header");
  return samples;
}

std::vector<PolarSample> read_polar_samples_csv(const std::filesystem::path& path) {
  return parse_polar_samples_csv(read_file(path, kMaxDocumentBytes), path.string());
}

std::string format_csv_number(double value) {
  std::array<char, 32> buffer{};
  const auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return ec == std::errc() ? std::string(buffer.data(), end) : std::string();
}

std::string polar_samples_csv_header(bool with_bearing) {
  std::string header = "theta_deg,radius_px,distance_cm";
  if (with_bearing) header += ",bearing_deg";
  return header;
}

std::string polar_sample_csv_row(const PolarSample& sample, bool with_bearing) {
  std::string row = format_csv_number(sample.theta_deg) + "," +
                    format_csv_number(sample.radius_px) + "," +
                    format_csv_number(sample.distance_cm);
  if (with_bearing) {
    row += ",";
    if (sample.bearing_deg) row += format_csv_number(*sample.bearing_deg);
  }
  return row;
}

bool any_bearing(std::span<const PolarSample> samples) {
  for (const PolarSample& s : samples) {
    if (s.bearing_deg) return true;
  }
  return false;
}

std::string format_polar_samples_csv(std::span<const PolarSample> samples) {
  const bool with_bearing = any_bearing(samples);
  std::string text = polar_samples_csv_header(with_bearing) + "\n";
  for (const PolarSample& s : samples) text += polar_sample_csv_row(s, with_bearing) + "\n";
  return text;
}

void write_polar_samples_csv(const std::filesystem::path& path,
                             std::span<const PolarSample> samples) {
  write_file_atomic(path, format_polar_samples_csv(samples));
}

}  // namespace ballsight
