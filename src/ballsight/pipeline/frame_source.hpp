#pragma once
// Where a camera's frames come from: recorded images (a file or a folder of files) or a live
// stream (a video device or a network URL, through cv::VideoCapture). A source may fail at any
// time (a camera disconnects); the capture thread then reopens it with back-off.

#include <chrono>
#include <filesystem>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

namespace ballsight {

/// How long to wait before reopening a source that failed: `initial`, then `factor` times longer
/// after every further failure in a row, never more than `max`.
struct BackoffOptions {
  std::chrono::milliseconds initial{200};
  std::chrono::milliseconds max{5000};
  double factor = 2.0;

  /// Throws InputError naming the first invalid field.
  void validate() const;
  /// Wait before attempt number `failures` + 1 after `failures` failures in a row (>= 1).
  std::chrono::milliseconds after(int failures) const;
};

class FrameSource {
 public:
  virtual ~FrameSource() = default;

  /// What it is, for messages ("folder frames/cam0", "rtsp://...").
  virtual std::string describe() const = 0;
  /// Opens it, or reopens it after a failure. Throws std::runtime_error saying why it cannot.
  virtual void open() = 0;
  /// The next frame; nullopt at the end of a recorded stream. Throws std::runtime_error when the
  /// source fails (the capture thread then reopens it).
  virtual std::optional<cv::Mat> read() = 0;
  /// Recorded sources are read completely, every frame in turn; live ones are read as fast as
  /// they come and stale frames are dropped.
  virtual bool live() const = 0;
};

/// Recorded images, read in the order given (a file source is one image).
std::unique_ptr<FrameSource> make_image_files_source(std::vector<std::filesystem::path> files,
                                                     std::string description);
/// Every image file of a folder (those OpenCV can read), in name order, listed when opened.
std::unique_ptr<FrameSource> make_image_folder_source(const std::filesystem::path& folder);
/// A video device (index) through cv::VideoCapture.
std::unique_ptr<FrameSource> make_device_source(int device);
/// A network stream or a video file through cv::VideoCapture.
std::unique_ptr<FrameSource> make_url_source(std::string url);

}  // namespace ballsight
