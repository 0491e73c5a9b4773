#include "ballsight/plan/tsplib.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "ballsight/core/csv_fields.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"

namespace ballsight::eval {
namespace {

// TSPLIB 95, section 2: the distance functions, rounded as the library defines them.
double geo_radians(double v) {
  const double pi = 3.141592;  // TSPLIB's own value
  const double deg = std::trunc(v);
  return pi * (deg + 5.0 * (v - deg) / 3.0) / 180.0;
}

double coordinate_distance(const std::string& type, const double* a, const double* b) {
  const double dx = a[0] - b[0], dy = a[1] - b[1];
  if (type == "EUC_2D") return std::round(std::sqrt(dx * dx + dy * dy));
  if (type == "CEIL_2D") return std::ceil(std::sqrt(dx * dx + dy * dy));
  if (type == "ATT") {
    const double r = std::sqrt((dx * dx + dy * dy) / 10.0);
    const double t = std::round(r);
    return t < r ? t + 1.0 : t;
  }
  // GEO
  const double lat_a = geo_radians(a[0]), lon_a = geo_radians(a[1]);
  const double lat_b = geo_radians(b[0]), lon_b = geo_radians(b[1]);
  const double q1 = std::cos(lon_a - lon_b), q2 = std::cos(lat_a - lat_b),
               q3 = std::cos(lat_a + lat_b);
  const double cosine = std::clamp(0.5 * ((1.0 + q1) * q2 - (1.0 - q1) * q3), -1.0, 1.0);
  return std::trunc(6378.388 * std::acos(cosine) + 1.0);
}

/// Fills `cost` from the explicit weights in `format` (their count checked), read row by row.
void fill_explicit(const std::string& format, const std::vector<double>& w, std::size_t n,
                   std::vector<std::vector<double>>& cost) {
  std::size_t k = 0;
  const auto next = [&] { return w[k++]; };
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t from = 0, to = n;  // columns of row i in the file
    if (format == "UPPER_ROW") from = i + 1;
    if (format == "UPPER_DIAG_ROW") from = i;
    if (format == "LOWER_ROW") to = i;
    if (format == "LOWER_DIAG_ROW") to = i + 1;
    for (std::size_t j = from; j < to; ++j) cost[i][j] = cost[j][i] = next();
  }
}

}  // namespace

TsplibInstance parse_tsplib(std::string_view text, const std::string& source) {
  TsplibInstance out;
  std::map<std::string, std::string> spec;
  std::vector<double> weights;
  std::vector<std::array<double, 2>> coords;
  std::istringstream in{std::string(text)};
  std::string line, section;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    const std::string t(trim_blanks(line));
    if (t.empty()) continue;
    const std::string at = source + ":" + std::to_string(line_number);
    if (t == "EOF") break;
    if (t.find("_SECTION") != std::string::npos) {
      section = t;
      continue;
    }
    const auto colon = t.find(':');
    if (section.empty() ||
        (colon != std::string::npos && std::isalpha(static_cast<unsigned char>(t[0])))) {
      require(colon != std::string::npos, at, "expected 'KEY : value'");
      spec[std::string(trim_blanks(t.substr(0, colon)))] = trim_blanks(t.substr(colon + 1));
      section.clear();
      continue;
    }
    std::istringstream values(t);
    double v;
    std::vector<double> row;
    while (values >> v) row.push_back(v);
    require(values.eof(), at, "expected numbers in " + section);
    if (section == "EDGE_WEIGHT_SECTION") weights.insert(weights.end(), row.begin(), row.end());
    if (section == "NODE_COORD_SECTION") {
      require(row.size() == 3, at, "expected 'index x y'");
      coords.push_back({row[1], row[2]});
    }
  }
  require(spec["TYPE"] == "TSP", source, "TYPE must be TSP, got '" + spec["TYPE"] + "'");
  out.name = spec["NAME"];
  if (out.name.size() > 4 && out.name.ends_with(".tsp")) out.name.resize(out.name.size() - 4);
  const int n = std::atoi(spec["DIMENSION"].c_str());
  require(n >= 3 && n <= 10000, source, "DIMENSION must be in [3, 10000]");
  const auto size = static_cast<std::size_t>(n);
  const std::string type = spec["EDGE_WEIGHT_TYPE"];
  require(type == "EXPLICIT" || coords.size() == size, source,
          "NODE_COORD_SECTION needs " + std::to_string(n) + " nodes, got " +
              std::to_string(coords.size()));
  out.cost.assign(size, std::vector<double>(size, 0.0));
  if (type == "EXPLICIT") {
    const std::string format = spec["EDGE_WEIGHT_FORMAT"];
    require(format == "FULL_MATRIX" || format == "UPPER_ROW" || format == "LOWER_ROW" ||
                format == "UPPER_DIAG_ROW" || format == "LOWER_DIAG_ROW",
            source, "EDGE_WEIGHT_FORMAT '" + format + "' is not supported");
    const std::size_t diagonal = format.find("DIAG") != std::string::npos ? size : 0;
    const std::size_t expected =
        format == "FULL_MATRIX" ? size * size : size * (size - 1) / 2 + diagonal;
    require(weights.size() == expected, source,
            "EDGE_WEIGHT_SECTION needs " + std::to_string(expected) + " weights, got " +
                std::to_string(weights.size()));
    fill_explicit(format, weights, size, out.cost);
  } else {
    require(type == "EUC_2D" || type == "CEIL_2D" || type == "GEO" || type == "ATT", source,
            "EDGE_WEIGHT_TYPE '" + type + "' is not supported");
    for (std::size_t i = 0; i < size; ++i) {
      for (std::size_t j = i + 1; j < size; ++j) {
        out.cost[i][j] = out.cost[j][i] =
            coordinate_distance(type, coords[i].data(), coords[j].data());
      }
    }
  }
  return out;
}

TsplibInstance read_tsplib(const std::filesystem::path& file) {
  return parse_tsplib(read_file(file), file.string());
}

std::map<std::string, double> parse_tsplib_optima(std::string_view text) {
  std::map<std::string, double> optima;
  std::istringstream in{std::string(text)};
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::string name, bound;
    int n = 0;
    double solution = 0.0;
    if (row >> name >> n >> solution >> bound && bound == "opt") optima[name] = solution;
  }
  return optima;
}

double tour_length(const TsplibInstance& instance, const std::vector<int>& order) {
  double total = 0.0;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const auto a = static_cast<std::size_t>(order[i]);
    const auto b = static_cast<std::size_t>(order[(i + 1) % order.size()]);
    total += instance.cost[a][b];
  }
  return total;
}

}  // namespace ballsight::eval
