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

cv::Mat decode_image_bgr(std::string_view bytes, const std::string& where,
                         std::optional<cv::Size> expected_size) {
  const std::vector<uchar> buffer(bytes.begin(), bytes.end());
  const cv::Mat image = buffer.empty() ? cv::Mat() : cv::imdecode(buffer, cv::IMREAD_COLOR);
  require(!image.empty(), where, "not a readable image (PNG, JPEG, ...)");
  if (expected_size) {
    require(image.size() == *expected_size, where,
            "image is " + size_text(image.size()) + ", expected " + size_text(*expected_size));
  }
  return image;
}

cv::Mat read_image_bgr(const std::filesystem::path& path, std::optional<cv::Size> expected_size) {
  return decode_image_bgr(read_file(path), path.string(), expected_size);
}

namespace {

std::string encoded(const cv::Mat& image, const char* extension, const std::vector<int>& params,
                    const std::string& where) {
  std::vector<uchar> bytes;
  require(!image.empty() && cv::imencode(extension, image, bytes, params), where,
          std::string("cannot encode ") + (extension + 1));
  return std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

}  // namespace

std::string png_bytes(const cv::Mat& image, const std::string& where) {
  return encoded(image, ".png", {}, where);
}

std::string jpeg_bytes(const cv::Mat& image, int quality, const std::string& where) {
  return encoded(image, ".jpg", {cv::IMWRITE_JPEG_QUALITY, quality}, where);
}

void write_png_atomic(const std::filesystem::path& path, const cv::Mat& image) {
  write_file_atomic(path, png_bytes(image, path.string()));
}

}  // namespace ballsight
