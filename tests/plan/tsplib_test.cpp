// The route planner as a plain shortest-tour solver on the TSPLIB instances Debian's glpk-utils
// ships, against their published optima (GLPK's bench.txt), at the default effort.
#include "ballsight/plan/tsplib.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/plan/planner.hpp"
#include "skip.hpp"

namespace ballsight::eval {
namespace {

TEST(Tsplib, ParsesEveryWeightFormatTheSameWay) {
  const std::string full =
      "NAME: t\nTYPE: TSP\nDIMENSION: 3\nEDGE_WEIGHT_TYPE: EXPLICIT\n"
      "EDGE_WEIGHT_FORMAT: FULL_MATRIX\nEDGE_WEIGHT_SECTION\n0 1 2\n1 0 3\n2 3 0\nEOF\n";
  const std::string lower =
      "NAME: t\nTYPE: TSP\nDIMENSION: 3\nEDGE_WEIGHT_TYPE: EXPLICIT\n"
      "EDGE_WEIGHT_FORMAT: LOWER_DIAG_ROW\nEDGE_WEIGHT_SECTION\n0\n1 0\n2 3 0\nEOF\n";
  const std::string euc =
      "NAME: t\nTYPE: TSP\nDIMENSION: 3\nEDGE_WEIGHT_TYPE: EUC_2D\n"
      "NODE_COORD_SECTION\n1 0 0\n2 1 0\n3 0 2.2\nEOF\n";
  const auto with = [](const std::string& format, const std::string& weights) {
    return "NAME: t\nTYPE: TSP\nDIMENSION: 3\nEDGE_WEIGHT_TYPE: EXPLICIT\nEDGE_WEIGHT_FORMAT: " +
           format + "\nEDGE_WEIGHT_SECTION\n" + weights + "\nEOF\n";
  };
  const auto expected = parse_tsplib(full, "full").cost;
  EXPECT_EQ(expected, parse_tsplib(lower, "lower").cost);
  EXPECT_EQ(expected, parse_tsplib(with("UPPER_ROW", "1 2 3"), "upper").cost);
  EXPECT_EQ(expected, parse_tsplib(with("LOWER_ROW", "1 2 3"), "lower_row").cost);
  EXPECT_EQ(expected, parse_tsplib(with("UPPER_DIAG_ROW", "0 1 2 0 3 0"), "upper_diag").cost);
  EXPECT_THROW(parse_tsplib(with("UPPER_ROW", "1 2"), "short"), InputError);
  EXPECT_THROW(parse_tsplib("NAME: t\nTYPE: TSP\nDIMENSION: 200000\nEDGE_WEIGHT_TYPE: "
                            "EUC_2D\nNODE_COORD_SECTION\n1 0 0\nEOF\n",
                            "huge"),
               InputError);
  // CEIL_2D rounds up, ATT is the pseudo-Euclidean distance of TSPLIB 95 (att48).
  const std::string coords = "NODE_COORD_SECTION\n1 0 0\n2 1 0\n3 0 2.2\nEOF\n";
  EXPECT_EQ(
      parse_tsplib("TYPE: TSP\nDIMENSION: 3\nEDGE_WEIGHT_TYPE: CEIL_2D\n" + coords, "c").cost[1][2],
      3.0);  // ceil(2.42)
  EXPECT_EQ(
      parse_tsplib("TYPE: TSP\nDIMENSION: 3\nEDGE_WEIGHT_TYPE: ATT\n" + coords, "att").cost[0][2],
      1.0);  // sqrt(4.84 / 10) = 0.696, nint 1
  // GEO: two of ulysses16's cities, 1 and 2 (38.24 20.42; 39.57 26.15): 509 km in TSPLIB units.
  EXPECT_EQ(parse_tsplib("TYPE: TSP\nDIMENSION: 3\nEDGE_WEIGHT_TYPE: GEO\nNODE_COORD_SECTION\n"
                         "1 38.24 20.42\n2 39.57 26.15\n3 40.56 25.32\nEOF\n",
                         "geo")
                .cost[0][1],
            509.0);
  EXPECT_EQ(parse_tsplib(euc, "euc").cost[1][2], 2.0);  // nint(sqrt(1 + 4.84)) = 2
  EXPECT_THROW(parse_tsplib("NAME: t\nTYPE: ATSP\nDIMENSION: 3\n", "atsp"), InputError);
}

TEST(Tsplib, WithinOnePercentOfThePublishedOptima) {
  if (!std::filesystem::exists(kGlpkTspDir / "bench.txt")) {
    BALLSIGHT_SKIP() << kGlpkTspDir << " missing (Debian package glpk-utils)";
  }
  const auto optima = parse_tsplib_optima(read_file(kGlpkTspDir / "bench.txt"));
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kGlpkTspDir)) {
    if (entry.path().extension() != ".tsp") continue;
    const TsplibInstance instance = read_tsplib(entry.path());
    const auto optimum = optima.find(instance.name);
    if (optimum == optima.end()) continue;  // no published optimum (moscow, sample)
    const std::vector<int> tour = shortest_tour(instance.cost, PlannerOptions{});
    std::vector<int> sorted = tour;
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], static_cast<int>(i));
    const double length = tour_length(instance, tour);
    EXPECT_GE(length, optimum->second) << instance.name;
    EXPECT_LE(length, 1.01 * optimum->second) << instance.name;
    ++checked;
  }
  EXPECT_EQ(checked, 4);  // ulysses16, ulysses22, dantzig42, gr120
}

}  // namespace
}  // namespace ballsight::eval
