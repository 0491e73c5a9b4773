#pragma once
// Calibration samples as CSV: header `theta_deg,radius_px,distance_cm` (any order) and an
// optional `bearing_deg` column, one sample per line. Bad input throws InputError
// "FILE:LINE:COLUMN: what was expected" (COLUMN: 1-based character column of the field).

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ballsight/calib/polar_sample.hpp"

namespace ballsight {

/// Parses CSV text; `source` names the text in error messages (usually the file path).
std::vector<PolarSample> parse_polar_samples_csv(std::string_view text, const std::string& source);

/// Reads a samples file; errors name the file, line and column.
std::vector<PolarSample> read_polar_samples_csv(const std::filesystem::path& path);

/// The header line (no newline); with `bearing_deg` when `with_bearing`.
std::string polar_samples_csv_header(bool with_bearing);
/// One data line (no newline) with shortest round-trip numbers; an absent bearing is empty.
std::string polar_sample_csv_row(const PolarSample& sample, bool with_bearing);
/// Whether any sample has a bearing (so a file of them needs the column).
bool any_bearing(std::span<const PolarSample> samples);

/// The whole file text: header and one line per sample.
std::string format_polar_samples_csv(std::span<const PolarSample> samples);

/// Writes the samples atomically.
void write_polar_samples_csv(const std::filesystem::path& path,
                             std::span<const PolarSample> samples);

/// Shortest text that reads back as exactly `value` ("81", "143.355").
std::string format_csv_number(double value);

}  // namespace ballsight
