#pragma once
// Camera image files: reading with errors that name the file, atomic PNG writes.

#include <cstddef>
#include <filesystem>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <string_view>

namespace ballsight {

/// Images larger than this many pixels are refused before they are decoded: 1 GiB as 8-bit BGR.
inline constexpr std::size_t kMaxImagePixels = (std::size_t{1} << 30) / 3;

/// The width and height a PNG or JPEG file's header declares; nullopt for another format or a
/// header cut short. Known before anything is decoded.
std::optional<cv::Size> declared_image_size(std::string_view bytes);

/// Decodes an image file's bytes as 8-bit BGR (a 16-bit image scaled to 8 bits, a greyscale one
/// given three equal channels); throws InputError naming `where` when they are not a readable
/// image (a JPEG without an end-of-image marker after its scan is taken for truncated), when
/// its size differs from `expected_size`, or when its header declares more than `max_pixels` pixels
/// (refused before decoding; other formats than PNG and JPEG are bounded by OpenCV's own limit,
/// 2^30 pixels).
cv::Mat decode_image_bgr(std::string_view bytes, const std::string& where,
                         std::optional<cv::Size> expected_size = std::nullopt,
                         std::size_t max_pixels = kMaxImagePixels);
/// Reads a colour image as 8-bit BGR; throws InputError naming the file when it cannot be read
/// or decoded, or when its size differs from `expected_size`.
cv::Mat read_image_bgr(const std::filesystem::path& path,
                       std::optional<cv::Size> expected_size = std::nullopt);

/// `image` encoded as PNG; throws InputError naming `where` when it cannot be.
std::string png_bytes(const cv::Mat& image, const std::string& where);
/// `image` encoded as JPEG of `quality` (0-100); throws InputError naming `where` when it cannot
/// be.
std::string jpeg_bytes(const cv::Mat& image, int quality, const std::string& where);
/// Encodes `image` as PNG and writes it atomically (temporary file, then rename).
void write_png_atomic(const std::filesystem::path& path, const cv::Mat& image);

}  // namespace ballsight
