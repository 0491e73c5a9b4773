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

// libjpeg decodes a cut JPEG with the missing rows grey and a warning; it is refused instead. A
// 16-bit PNG is scaled to 8 bits and a greyscale one given three channels.
TEST(ImageFile, ATruncatedJpegIsAnErrorAndOtherDepthsAreConverted) {
  cv::Mat image(240, 320, CV_8UC3);
  cv::randu(image, cv::Scalar::all(0), cv::Scalar::all(255));
  const std::string jpeg = encoded(image, ".jpg");
  EXPECT_EQ(decode_image_bgr(jpeg, "whole.jpg").size(), image.size());
  try {
    decode_image_bgr(jpeg.substr(0, jpeg.size() / 2), "cut.jpg");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "cut.jpg: JPEG without its end-of-image marker: truncated");
  }
  // More than a kilobyte after the end (a phone's appended data) is no truncation; an end marker
  // inside a segment before the scan (an EXIF thumbnail's) does not hide one.
  EXPECT_EQ(decode_image_bgr(jpeg + std::string(4096, '\0'), "trailer.jpg").size(), image.size());
  const std::string app1 = std::string("\xFF\xE1\x00\x09thumb", 9) + "\xFF\xD9";
  const std::string with_thumbnail = jpeg.substr(0, 2) + app1 + jpeg.substr(2);
  EXPECT_EQ(decode_image_bgr(with_thumbnail, "thumb.jpg").size(), image.size());
  EXPECT_THROW(decode_image_bgr(with_thumbnail.substr(0, with_thumbnail.size() / 2), "cut.jpg"),
               InputError);
  cv::Mat deep;
  image.convertTo(deep, CV_16UC3, 257.0);
  const cv::Mat from_deep = decode_image_bgr(encoded(deep, ".png"), "deep.png");
  ASSERT_EQ(from_deep.type(), CV_8UC3);
  EXPECT_EQ(cv::norm(from_deep, image, cv::NORM_INF), 0.0);
  cv::Mat grey(10, 20, CV_8UC1, cv::Scalar(77));
  const cv::Mat from_grey = decode_image_bgr(encoded(grey, ".png"), "grey.png");
  ASSERT_EQ(from_grey.type(), CV_8UC3);
  EXPECT_EQ(from_grey.at<cv::Vec3b>(5, 5), cv::Vec3b(77, 77, 77));
}

}  // namespace
}  // namespace ballsight
