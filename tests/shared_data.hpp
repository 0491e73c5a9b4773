#pragma once
// The reference data beside the project (../shared/data, see its README.md); tests that use it
// skip with a message when it is absent.

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace ballsight::test {

inline std::filesystem::path shared_data_dir() {
  return BALLSIGHT_SHARED_DATA_DIR;
}

/// The IRIS robots' px2cm tables in shared/data/iris-lut, sorted; empty when absent.
inline std::vector<std::filesystem::path> iris_px2cm_tables() {
  std::vector<std::filesystem::path> tables;
  const std::filesystem::path dir = shared_data_dir() / "iris-lut";
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.find("px2cm") != std::string::npos && entry.path().extension() == ".bin") {
      tables.push_back(entry.path());
    }
  }
  std::sort(tables.begin(), tables.end());
  return tables;
}

}  // namespace ballsight::test
