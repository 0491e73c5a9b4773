#pragma once
// A site whose cameras are recorded: two simulated scenes (`ballsight sim court`, 1280 x 720 in
// sun: the light conditions are measured by `eval court`), each camera's frames in a folder of
// its own, its true calibration in camC.yml, and the example site pointing at the folders. For the
// CLI tests of `court run` and `serve --site`.

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "apps/run_cli.hpp"
#include "ballsight/camera/camera_file.hpp"
#include "ballsight/core/file_io.hpp"
#include "example_site.hpp"
#include "temp_dir.hpp"

namespace ballsight::test {

inline const char* const kNames[] = {"ne", "se", "sw", "nw"};

// Two simulated scenes, each camera's frames in its own folder, its true calibration in camC.yml,
// and the example site with folder sources.
inline std::filesystem::path simulated_site(const TempDir& temp) {
  const std::filesystem::path dir = temp / "site";
  const CliResult sim = run_cli({"sim", "court", "--out", dir.string(), "--seed", "4", "--scenes",
                                 "2", "--width", "1280", "--height", "720", "--light", "sun"});
  EXPECT_EQ(sim.exit_code, 0) << sim.stderr_text;
  const nlohmann::json truth = nlohmann::json::parse(read_file(dir / "court_0000.json"));
  for (int c = 0; c < 4; ++c) {
    const std::string cam = "cam" + std::to_string(c);
    std::filesystem::create_directories(dir / cam);
    for (int k = 0; k < 2; ++k) {
      const std::string image = "court_000" + std::to_string(k) + "_" + cam + ".png";
      std::filesystem::rename(dir / image, dir / cam / image);
    }
    const nlohmann::json& t = truth["cameras"][c];
    CameraCalibration calibration;
    PinholeParams& p = calibration.intrinsics;
    p.width = t["width"];
    p.height = t["height"];
    p.fx = t["fx"];
    p.fy = t["fy"];
    p.cx = t["cx"];
    p.cy = t["cy"];
    for (size_t i = 0; i < 8; ++i) p.distortion[i] = t["distortion"][i];
    const auto& pose = t["camera_from_field"];
    calibration.extrinsics = CameraExtrinsics{
        Rigid3::from_rvec_tvec(Vec3(pose["rvec"][0], pose["rvec"][1], pose["rvec"][2]),
                               Vec3(pose["tvec"][0], pose["tvec"][1], pose["tvec"][2])),
        0.1, 12};
    write_camera_file(dir / (cam + ".yml"), calibration);
  }
  std::string site = read_file(kExampleSite);
  for (int c = 0; c < 4; ++c) {
    const std::string from = "{file: court_0000_cam" + std::to_string(c) + ".png}";
    site.replace(site.find(from), from.size(), "{folder: cam" + std::to_string(c) + "}");
  }
  write_file_atomic(dir / "site.yml", site);
  return dir / "site.yml";
}

}  // namespace ballsight::test
