// `ballsight calibrate camera`: a camera's intrinsics from chessboard photos, written as OpenCV
// FileStorage YAML (docs/site-file.md).

#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#include "ballsight/calib/chessboard_images.hpp"
#include "ballsight/calib/intrinsics.hpp"
#include "ballsight/camera/camera_file.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/glob.hpp"
#include "ballsight/core/text_format.hpp"
#include "commands.hpp"

namespace ballsight::app {
namespace {

struct CalibrateCameraArgs {
  std::string images;
  std::string board = "9x6";
  double square_m = 0.0;
  std::string out;
};

/// "COLSxROWS" inner corners, e.g. "9x6".
ChessboardPattern parse_board(const std::string& text, double square_m) {
  ChessboardPattern pattern;
  char x = 0, extra = 0;
  const bool ok = std::sscanf(text.c_str(), "%d%c%d%c", &pattern.inner_cols, &x,
                              &pattern.inner_rows, &extra) == 3 &&
                  (x == 'x' || x == 'X');
  require(ok, "--board", "expected inner corners as COLSxROWS, e.g. 9x6, got '" + text + "'");
  pattern.square_m = square_m;
  pattern.validate();
  return pattern;
}

void run_calibrate_camera(const CalibrateCameraArgs& args) {
  const ChessboardPattern pattern = parse_board(args.board, args.square_m);
  const ChessboardImages images = find_chessboards_in_images(glob_files(args.images), pattern);
  require(!images.found.empty(), args.images,
          "the " + args.board + " board was not found in any of the " +
              std::to_string(images.not_found.size()) +
              " image(s) (check --board: inner corners, not squares)");
  const IntrinsicsResult result = calibrate_intrinsics(images.found, pattern, images.image_size);

  for (const ViewError& view : result.views) {
    std::cout << view.name << ": " << fixed(view.rms_px, 3) << " px"
              << (view.outlier ? " (outlier, skipped)" : "") << "\n";
  }
  for (const std::string& name : images.not_found) {
    std::cout << name << ": board not found (skipped)\n";
  }
  int used = 0;
  for (const ViewError& view : result.views) used += view.outlier ? 0 : 1;
  const PinholeParams& p = result.camera;
  std::cout << "calibrated from " << used << " of " << images.found.size() + images.not_found.size()
            << " images (" << images.image_size.width << "x" << images.image_size.height
            << "): reprojection rms " << fixed(result.rms_px, 3) << " px\n"
            << "fx " << fixed(p.fx, 2) << " fy " << fixed(p.fy, 2) << " cx " << fixed(p.cx, 2)
            << " cy " << fixed(p.cy, 2) << " px; k1 " << fixed(p.distortion[0], 5) << " k2 "
            << fixed(p.distortion[1], 5) << " p1 " << fixed(p.distortion[2], 6) << " p2 "
            << fixed(p.distortion[3], 6) << " k3 " << fixed(p.distortion[4], 5)
            << (result.k3_free ? "" : " (fixed)") << "\n";
  if (result.heldout_rms_fixed_k3_px && result.heldout_rms_free_k3_px) {
    std::cout << "held-out rms: k3 fixed " << fixed(*result.heldout_rms_fixed_k3_px, 3)
              << " px, k3 free " << fixed(*result.heldout_rms_free_k3_px, 3) << " px\n";
  }
  CameraCalibration calibration;
  calibration.intrinsics = result.camera;
  calibration.avg_reprojection_error_px = result.rms_px;
  write_camera_file(args.out, calibration);
  std::cout << "wrote " << args.out << "\n";
}

}  // namespace

void add_calibrate_camera_command(CLI::App& calibrate) {
  auto args = std::make_shared<CalibrateCameraArgs>();
  CLI::App* cmd = calibrate.add_subcommand(
      "camera",
      "Intrinsics (camera matrix, distortion) from chessboard photos, as OpenCV FileStorage YAML");
  cmd->add_option("--images", args->images,
                  "Chessboard photos: a file name pattern with * and ? (quote it), e.g. "
                  "'calib/left*.jpg'")
      ->required();
  cmd->add_option("--board", args->board, "Inner corners per row x per column, e.g. 9x6")
      ->capture_default_str();
  cmd->add_option("--square", args->square_m, "Side of a square, metres")->required();
  cmd->add_option("--out", args->out, "Calibration file to write (YAML)")->required();
  cmd->callback([args] { run_calibrate_camera(*args); });
}

}  // namespace ballsight::app
