// `ballsight omni fit` and `ballsight omni predict` end to end: models and predictions written,
// and bad input ends with one line on stderr, exit status 2 and any existing output untouched.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

#include "apps/run_cli.hpp"
#include "ballsight/core/file_io.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

namespace fs = std::filesystem;

// Markers every 10 deg at 60 .. 460 cm on an ideal catadioptric rig (the unified model's floor
// profile, xi 0.5, focal 128 px, 60 cm high), written by hand.
std::string synthetic_samples_csv(double degree_step = 10.0) {
  std::ostringstream csv;
  csv << "theta_deg,radius_px,distance_cm\n";
  for (double theta = 0.0; theta < 360.0; theta += degree_step) {
    for (double d = 60.0; d <= 460.0; d += 50.0) {
      const double phi = std::atan2(d, 60.0);
      csv << theta << "," << 128.0 * std::sin(phi) / (std::cos(phi) + 0.5) << "," << d << "\n";
    }
  }
  return csv.str();
}

class OmniFitCli : public ::testing::Test {
 protected:
  void SetUp() override { write_file_atomic(samples(), synthetic_samples_csv()); }

  fs::path samples() const { return dir / "samples.csv"; }

  /// Bad input: exit 2, one line on stderr containing `problem`, `kept` left as it was.
  static void expect_rejected(const std::vector<std::string>& args, const std::string& problem,
                              const fs::path& kept) {
    write_file_atomic(kept, "previous content\n");
    const test::CliResult r = test::run_cli(args);
    EXPECT_EQ(r.exit_code, 2) << r.stderr_text;
    EXPECT_EQ(test::line_count(r.stderr_text), 1) << r.stderr_text;
    EXPECT_NE(r.stderr_text.find(problem), std::string::npos) << r.stderr_text;
    EXPECT_EQ(read_file(kept), "previous content\n");
  }

  test::TempDir dir;
};

TEST_F(OmniFitCli, FitsThenPredicts) {
  for (const std::string method : {"poly", "ballsight"}) {
    SCOPED_TRACE(method);
    const fs::path model = dir / (method + ".json");
    const fs::path lut = dir / (method + ".bsgm");
    const test::CliResult fit =
        test::run_cli({"omni", "fit", "--samples", samples().string(), "--method", method, "--out",
                       lut.string(), "--image-size", "640x480", "--model", model.string()});
    ASSERT_EQ(fit.exit_code, 0) << fit.stderr_text;
    EXPECT_EQ(test::line_count(fit.stdout_text), 1) << fit.stdout_text;
    EXPECT_NE(read_file(model).find("\"method\": \"" + method + "\""), std::string::npos);
    EXPECT_EQ(read_file(lut).substr(0, 8), "BSGRDMAP");

    for (const std::string table_option : {"--lut", "--model"}) {
      SCOPED_TRACE(table_option);
      const fs::path predictions = dir / (method + ".csv");
      const test::CliResult predict = test::run_cli(
          {"omni", "predict", table_option, (table_option == "--lut" ? lut : model).string(),
           "--samples", samples().string(), "--out", predictions.string()});
      ASSERT_EQ(predict.exit_code, 0) << predict.stderr_text;
      std::istringstream in(read_file(predictions));
      std::string line;
      std::getline(in, line);
      EXPECT_EQ(line,
                "theta_deg,radius_px,distance_cm,predicted_distance_cm,predicted_bearing_deg,"
                "in_range");
      int rows = 0;
      while (std::getline(in, line)) {
        ++rows;
        EXPECT_EQ(line.back(), '1') << line;  // every sample lies in the model's range
        // The prediction follows the sample's own distance closely on noise-free samples.
        std::istringstream fields(line);
        std::string theta, radius, distance, predicted;
        std::getline(fields, theta, ',');
        std::getline(fields, radius, ',');
        std::getline(fields, distance, ',');
        std::getline(fields, predicted, ',');
        EXPECT_NEAR(std::stod(predicted), std::stod(distance), 0.05 * std::stod(distance)) << line;
      }
      EXPECT_EQ(rows, 36 * 9);
    }
  }
}

TEST_F(OmniFitCli, BadFitInputIsOneLineAndLeavesTheOutput) {
  const fs::path out = dir / "table.bsgm";
  const std::vector<std::string> fit = {"omni", "fit", "--out", out.string(), "--samples"};
  const auto with = [&](const std::string& samples_path, std::vector<std::string> more) {
    std::vector<std::string> args = fit;
    args.push_back(samples_path);
    args.insert(args.end(), more.begin(), more.end());
    return args;
  };
  const fs::path bad = dir / "bad.csv";
  write_file_atomic(bad, "theta_deg,radius_px,distance_cm\n0,81,60\n10,nan,60\n");
  expect_rejected(with(bad.string(), {}), bad.string() + ":3:4: radius_px", out);
  const fs::path few = dir / "few.csv";
  write_file_atomic(few, "theta_deg,radius_px,distance_cm\n0,81,60\n0,105,110\n0,143,160\n");
  expect_rejected(with(few.string(), {"--method", "poly"}), "needs at least 7 samples", out);
  expect_rejected(with(few.string(), {"--method", "paper-mlp"}), "needs at least 8 samples", out);
  expect_rejected(with(samples().string(), {"--method", "cubic"}), "unknown method 'cubic'", out);
  expect_rejected(with(samples().string(), {"--image-size", "0x480"}),
                  "--image-size: expected a size WxH", out);
  expect_rejected(with(samples().string(), {"--image-size", "big"}), "--image-size", out);
  expect_rejected(with(samples().string(), {"--image-size", "160x120"}), "beyond every corner",
                  out);
  expect_rejected(with(samples().string(), {"--center", "1,2,3"}), "--center", out);
  expect_rejected(with(samples().string(), {"--degree", "3"}), "--degree: applies only", out);
  expect_rejected(with(samples().string(), {"--method", "poly", "--viewpoint-height-cm", "60"}),
                  "--viewpoint-height-cm: applies only", out);
  expect_rejected(with(samples().string(), {"--viewpoint-height-sigma-cm", "1"}),
                  "needs --viewpoint-height-cm", out);
  expect_rejected(with(samples().string(), {"--viewpoint-height-cm", "-5"}),
                  "viewpoint_height_cm: expected a positive number", out);
  expect_rejected(with((dir / "missing.csv").string(), {}), "missing.csv", out);
}

TEST_F(OmniFitCli, BadPredictInputIsOneLineAndLeavesTheOutput) {
  const fs::path model = dir / "model.json";
  ASSERT_EQ(test::run_cli({"omni", "fit", "--samples", samples().string(), "--method", "poly",
                           "--out", (dir / "table.bsgm").string(), "--model", model.string()})
                .exit_code,
            0);
  const fs::path out = dir / "predictions.csv";
  const fs::path broken = dir / "broken.json";
  write_file_atomic(broken, "{\"format\": ");
  expect_rejected({"omni", "predict", "--model", broken.string(), "--samples", samples().string(),
                   "--out", out.string()},
                  broken.string() + ": not valid JSON", out);
  const fs::path bad = dir / "bad.csv";
  write_file_atomic(bad, "theta_deg,radius_px,distance_cm\n0,81,60,7\n");
  expect_rejected({"omni", "predict", "--model", model.string(), "--samples", bad.string(), "--out",
                   out.string()},
                  bad.string() + ":2:9: extra column", out);
  expect_rejected({"omni", "predict", "--samples", samples().string(), "--out", out.string()},
                  "exactly one of --lut FILE and --model FILE", out);
  const fs::path truncated = dir / "truncated.bsgm";
  write_file_atomic(truncated, read_file(dir / "table.bsgm").substr(0, 1000));
  expect_rejected({"omni", "predict", "--lut", truncated.string(), "--samples", samples().string(),
                   "--out", out.string()},
                  truncated.string() + ": truncated", out);
}

}  // namespace
}  // namespace ballsight
