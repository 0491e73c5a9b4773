#include "ballsight/pipeline/frame_source.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>
#include <opencv2/videoio/registry.hpp>
#include <stdexcept>

#include "ballsight/camera/image_file.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {

void BackoffOptions::validate() const {
  require(initial.count() >= 0 && max >= initial, "backoff", "need 0 <= initial <= max");
  require(factor >= 1.0, "backoff factor", "must be at least 1");
}

std::chrono::milliseconds BackoffOptions::after(int failures) const {
  const double ms =
      static_cast<double>(initial.count()) * std::pow(factor, std::max(0, failures - 1));
  return std::chrono::milliseconds(
      static_cast<std::int64_t>(std::min(ms, static_cast<double>(max.count()))));
}

namespace {

std::vector<std::filesystem::path> list_images(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec))
    if (entry.is_regular_file(ec) && cv::haveImageReader(entry.path().string()))
      files.push_back(entry.path());
  if (ec) throw std::runtime_error("cannot list folder " + folder.string() + ": " + ec.message());
  if (files.empty()) throw std::runtime_error("no image in folder " + folder.string());
  std::sort(files.begin(), files.end());
  return files;
}

class ImageFilesSource final : public FrameSource {
 public:
  ImageFilesSource(std::vector<std::filesystem::path> files, std::string description,
                   std::optional<std::filesystem::path> folder = std::nullopt)
      : files_(std::move(files)),
        description_(std::move(description)),
        folder_(std::move(folder)) {}

  std::string describe() const override { return description_; }
  void open() override {
    if (folder_ && files_.empty()) files_ = list_images(*folder_);
  }
  std::optional<cv::Mat> read() override {
    if (next_ >= files_.size()) return std::nullopt;
    const std::filesystem::path& file = files_[next_];
    // read_image_bgr names the file and what is wrong with it (OpenCV's imread would print a
    // warning of its own on every retry).
    cv::Mat image = read_image_bgr(file);
    ++next_;
    return image;
  }
  bool live() const override { return false; }

 private:
  std::vector<std::filesystem::path> files_;
  std::string description_;
  std::optional<std::filesystem::path> folder_;  // listed when opened
  size_t next_ = 0;                              // a failed file is read again after the back-off
};

class VideoCaptureSource final : public FrameSource {
 public:
  VideoCaptureSource(std::optional<int> device, std::string url)
      : device_(device), url_(std::move(url)) {}

  std::string describe() const override {
    return device_ ? "video device " + std::to_string(*device_) : url_;
  }
  void open() override {
    capture_.release();
    // Backends named where OpenCV has them: after a failed open its default goes on to
    // GStreamer and an image-sequence reader, which print errors of their own on every retry of
    // an unreachable camera.
    const cv::VideoCaptureAPIs wanted = device_ ? cv::CAP_V4L2 : cv::CAP_FFMPEG;
    const cv::VideoCaptureAPIs api =
        cv::videoio_registry::hasBackend(wanted) ? wanted : cv::CAP_ANY;
    const bool ok = device_ ? capture_.open(*device_, api) : capture_.open(url_, api);
    if (!ok || !capture_.isOpened()) throw std::runtime_error("cannot open " + describe());
  }
  std::optional<cv::Mat> read() override {
    cv::Mat frame;
    if (!capture_.isOpened() || !capture_.read(frame) || frame.empty())
      throw std::runtime_error("no frame from " + describe() + " (disconnected?)");
    return frame;
  }
  bool live() const override { return true; }

 private:
  std::optional<int> device_;
  std::string url_;
  cv::VideoCapture capture_;
};

}  // namespace

std::unique_ptr<FrameSource> make_image_files_source(std::vector<std::filesystem::path> files,
                                                     std::string description) {
  return std::make_unique<ImageFilesSource>(std::move(files), std::move(description));
}

std::unique_ptr<FrameSource> make_image_folder_source(const std::filesystem::path& folder) {
  return std::make_unique<ImageFilesSource>(std::vector<std::filesystem::path>{},
                                            "folder " + folder.string(), folder);
}

std::unique_ptr<FrameSource> make_device_source(int device) {
  return std::make_unique<VideoCaptureSource>(device, "");
}

std::unique_ptr<FrameSource> make_url_source(std::string url) {
  return std::make_unique<VideoCaptureSource>(std::nullopt, std::move(url));
}

}  // namespace ballsight
