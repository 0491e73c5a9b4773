#pragma once
// Splitting one line of a CSV file (comma-separated, no quoting) into trimmed fields that remember
// where they start, so that a message can name the line and column of a bad value.

#include <cstddef>
#include <string_view>
#include <vector>

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

}  // namespace ballsight
