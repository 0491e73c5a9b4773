#pragma once
// The documented example site (docs/examples/site.yml: the simulator's court, its twelve
// reference balls and four corner cameras ne, se, sw, nw), for the tests that read it.

#include <filesystem>

namespace ballsight::test {

inline const std::filesystem::path kExampleSite =
    std::filesystem::path(BALLSIGHT_SOURCE_DIR) / "docs" / "examples" / "site.yml";

}  // namespace ballsight::test
