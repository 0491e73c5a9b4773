#pragma once
// TSPLIB 95 instances (Reinelt, "TSPLIB 95", 1995): symmetric TSP files with explicit weights
// (FULL_MATRIX, UPPER_ROW, LOWER_ROW, UPPER_DIAG_ROW, LOWER_DIAG_ROW) or coordinates (EUC_2D,
// CEIL_2D, GEO, ATT), and the published optima GLPK ships beside its examples (bench.txt), for
// checking the route planner as a plain shortest-tour solver.

#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace ballsight::eval {

struct TsplibInstance {
  std::string name;
  std::vector<std::vector<double>> cost;  // integral distances as TSPLIB defines them
};

/// Parses a .tsp file's text; throws InputError "<source>:<line>: ..." for what it cannot read.
TsplibInstance parse_tsplib(std::string_view text, const std::string& source);
TsplibInstance read_tsplib(const std::filesystem::path& file);

/// Instance name -> optimal tour length from a GLPK bench.txt table (rows marked "opt").
std::map<std::string, double> parse_tsplib_optima(std::string_view text);

/// Length of the closed tour `order` (every node once) under the instance's cost.
double tour_length(const TsplibInstance& instance, const std::vector<int>& order);

/// Where Debian's glpk-utils puts its TSPLIB examples.
inline const std::filesystem::path kGlpkTspDir = "/usr/share/doc/glpk-utils/examples/tsp";

}  // namespace ballsight::eval
