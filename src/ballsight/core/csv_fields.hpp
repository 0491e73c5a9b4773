#pragma once
// Splitting one line of a CSV file (comma-separated, no quoting) into trimmed fields that remember
// where they start, so that a message can name the line and column of a bad value.

#include <charconv>
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "ballsight/core/error.hpp"

namespace ballsight {

struct CsvField {
  std::string_view text;  // trimmed of blanks and tabs
  std::size_t column;     // 1-based character column where the field starts
};

inline std::string_view trim_blanks(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

inline std::vector<CsvField> split_csv_fields(std::string_view line) {
  std::vector<CsvField> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    const std::size_t end = comma == std::string_view::npos ? line.size() : comma;
    fields.push_back({trim_blanks(line.substr(start, end - start)), start + 1});
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

/// The field as a finite number; throws InputError "<where>:<column>: expected a finite number".
inline double csv_number(const CsvField& field, const std::string& where) {
  double value = 0.0;
  const auto [end, ec] =
      std::from_chars(field.text.data(), field.text.data() + field.text.size(), value);
  require(ec == std::errc() && end == field.text.data() + field.text.size() && std::isfinite(value),
          where + ":" + std::to_string(field.column),
          "expected a finite number, got '" + std::string(field.text) + "'");
  return value;
}

}  // namespace ballsight
