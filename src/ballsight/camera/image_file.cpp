#include "ballsight/camera/image_file.hpp"

#include <cstdint>
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

namespace {

std::uint32_t big_endian(std::string_view bytes, std::size_t at, std::size_t count) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < count; ++i) v = (v << 8) | static_cast<std::uint8_t>(bytes[at + i]);
  return v;
}

// JPEG: where the first segment whose marker `stop` accepts begins, walking the segments before
// it; nothing when the walk fails first.
template <typename Stop>
std::optional<std::size_t> jpeg_segment(std::string_view bytes, Stop stop) {
  std::size_t at = 2;
  while (at + 4 <= bytes.size()) {
    if (static_cast<std::uint8_t>(bytes[at]) != 0xFF) return std::nullopt;
    const auto marker = static_cast<std::uint8_t>(bytes[at + 1]);
    if (marker == 0xFF) {  // fill byte
      ++at;
      continue;
    }
    if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) {  // no length
      at += 2;
      continue;
    }
    if (stop(marker)) return at;
    const std::uint32_t length = big_endian(bytes, at + 2, 2);
    if (length < 2) return std::nullopt;
    at += 2 + length;
  }
  return std::nullopt;
}

// JPEG: the frame header (SOF0-SOF15 but DHT, JPG and DAC).
std::optional<cv::Size> jpeg_size(std::string_view bytes) {
  const std::optional<std::size_t> at = jpeg_segment(bytes, [](std::uint8_t marker) {
    return marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
  });
  if (!at || *at + 9 > bytes.size()) return std::nullopt;
  return cv::Size(static_cast<int>(big_endian(bytes, *at + 7, 2)),
                  static_cast<int>(big_endian(bytes, *at + 5, 2)));
}

// Whether a JPEG was cut short: its main image's scan (after the start-of-scan segment; an EXIF
// thumbnail's lies inside an APP1 segment before it) has no end-of-image marker after it. The
// entropy-coded data holds no 0xFF 0xD9 but that marker (0xFF bytes are stuffed).
bool jpeg_truncated(std::string_view bytes) {
  const std::optional<std::size_t> scan =
      jpeg_segment(bytes, [](std::uint8_t marker) { return marker == 0xDA; });
  return scan && bytes.find("\xFF\xD9", *scan) == std::string_view::npos;
}

}  // namespace

std::optional<cv::Size> declared_image_size(std::string_view bytes) {
  if (bytes.starts_with("\x89PNG\r\n\x1a\n")) {
    if (bytes.size() < 24 || bytes.substr(12, 4) != "IHDR") return std::nullopt;
    const std::uint32_t width = big_endian(bytes, 16, 4), height = big_endian(bytes, 20, 4);
    if (width > 0x7fffffff || height > 0x7fffffff) return std::nullopt;
    return cv::Size(static_cast<int>(width), static_cast<int>(height));
  }
  if (bytes.starts_with("\xff\xd8")) return jpeg_size(bytes);
  return std::nullopt;
}

cv::Mat decode_image_bgr(std::string_view bytes, const std::string& where,
                         std::optional<cv::Size> expected_size, std::size_t max_pixels) {
  if (const std::optional<cv::Size> declared = declared_image_size(bytes)) {
    const std::size_t pixels =
        static_cast<std::size_t>(declared->width) * static_cast<std::size_t>(declared->height);
    require(pixels <= max_pixels, where,
            "image of " + size_text(*declared) + " pixels is larger than the limit of " +
                std::to_string(max_pixels) + " pixels; not decoded");
  }
  // libjpeg decodes a truncated JPEG with a warning and fills the missing rows with grey.
  require(!bytes.starts_with("\xFF\xD8") || !jpeg_truncated(bytes), where,
          "JPEG without its end-of-image marker: truncated");
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
