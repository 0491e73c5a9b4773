#include "ballsight/camera/image_file.hpp"

#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"

namespace ballsight {

namespace {
std::string size_text(cv::Size size) {
  return std::to_string(size.width) + "x" + std::to_string(size.height);
}
}  // namespace

cv::Mat read_image_bgr(const std::filesystem::path& path, std::optional<cv::Size> expected_size) {
  const std::string bytes = read_file(path);
  const std::vector<uchar> buffer(bytes.begin(), bytes.end());
  const cv::Mat image = cv::imdecode(buffer, cv::IMREAD_COLOR);
  require(!image.empty(), path.string(), "not a readable image (PNG, JPEG, ...)");
  if (expected_size) {
    require(image.size() == *expected_size, path.string(),
            "image is " + size_text(image.size()) + ", expected " + size_text(*expected_size));
  }
  return image;
}

void write_png_atomic(const std::filesystem::path& path, const cv::Mat& image) {
  std::vector<uchar> png;
  require(!image.empty() && cv::imencode(".png", image, png), path.string(), "cannot encode PNG");
  write_file_atomic(path, std::string_view(reinterpret_cast<const char*>(png.data()), png.size()));
}

}  // namespace ballsight
