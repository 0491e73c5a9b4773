#include "ballsight/camera/image_file.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

std::string encoded(const cv::Mat& image, const char* extension) {
  std::vector<uchar> bytes;
  cv::imencode(extension, image, bytes);
  return std::string(bytes.begin(), bytes.end());
}

// A PNG's first chunk (IHDR) declaring `width` x `height`, and nothing after it.
std::string png_header(std::uint32_t width, std::uint32_t height) {
  std::string bytes = "\x89PNG\r\n\x1a\n";
  bytes += std::string("\0\0\0\x0dIHDR", 8);
  for (const std::uint32_t v : {width, height})
    for (int shift = 24; shift >= 0; shift -= 8) bytes += static_cast<char>((v >> shift) & 0xff);
  bytes += std::string("\x08\x02\0\0\0", 5);
  return bytes;
}

TEST(ImageFile, TheHeadersDeclaredSize) {
  const cv::Mat image(23, 37, CV_8UC3, cv::Scalar(10, 200, 30));
  EXPECT_EQ(declared_image_size(encoded(image, ".png")), cv::Size(37, 23));
  EXPECT_EQ(declared_image_size(encoded(image, ".jpg")), cv::Size(37, 23));
  EXPECT_EQ(declared_image_size(png_header(40000, 30000)), cv::Size(40000, 30000));
  EXPECT_FALSE(declared_image_size(encoded(image, ".bmp")));
  EXPECT_FALSE(declared_image_size("\x89PNG\r\n\x1a\n"));  // cut short
  EXPECT_FALSE(declared_image_size(std::string("\xff\xd8\xff\xe0\x00\x10JFIF", 10)));
  EXPECT_FALSE(declared_image_size("not an image"));
}

// An image whose header declares more pixels than the limit is refused before it is decoded (a
// few bytes that would make gigabytes); the message names the size and the limit.
TEST(ImageFile, TooManyPixelsAreRefusedBeforeDecoding) {
  try {
    decode_image_bgr(png_header(40000, 30000), "upload.png");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "upload.png: image of 40000x30000 pixels is larger than the limit of " +
                  std::to_string(kMaxImagePixels) + " pixels; not decoded");
  }
  const cv::Mat image(23, 37, CV_8UC3, cv::Scalar(10, 200, 30));
  EXPECT_THROW(decode_image_bgr(encoded(image, ".jpg"), "small.jpg", std::nullopt, 100),
               InputError);
  EXPECT_EQ(decode_image_bgr(encoded(image, ".png"), "ok.png", std::nullopt, 37 * 23).size(),
            image.size());
}

}  // namespace
}  // namespace ballsight
