#pragma once
// Writes the files of a simulated data set into one folder, atomically, remembering their names.

#include <filesystem>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "ballsight/camera/image_file.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/sim/json_io.hpp"

namespace ballsight::sim {

class DatasetWriter {
 public:
  explicit DatasetWriter(std::filesystem::path dir) : dir_(std::move(dir)) {
    ensure_directory(dir_);
  }

  void png(const std::string& name, const cv::Mat& image) {
    write_png_atomic(dir_ / name, image);
    written_.push_back(name);
  }

  void json(const std::string& name, const Json& document) {
    write_file_atomic(dir_ / name, json_text(document));
    written_.push_back(name);
  }

  std::vector<std::string> written() && { return std::move(written_); }

 private:
  std::filesystem::path dir_;
  std::vector<std::string> written_;
};

}  // namespace ballsight::sim
