#include "ballsight/calib/chessboard_images.hpp"

#include "ballsight/camera/image_file.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {

namespace {

std::string size_text(cv::Size size) {
  return std::to_string(size.width) + "x" + std::to_string(size.height);
}

}  // namespace

ChessboardImages find_chessboards_in_images(const std::vector<std::filesystem::path>& files,
                                            const ChessboardPattern& pattern) {
  pattern.validate();
  ChessboardImages session;
  for (const std::filesystem::path& file : files) {
    const cv::Mat image = read_image_bgr(file);
    if (session.image_size.empty()) session.image_size = image.size();
    require(image.size() == session.image_size, file.string(),
            "image is " + size_text(image.size()) + ", the first image (" + files.front().string() +
                ") is " + size_text(session.image_size) + ": every view must come from one camera");
    if (auto corners = find_chessboard_corners(image, pattern)) {
      session.found.push_back({file.string(), std::move(*corners)});
    } else {
      session.not_found.push_back(file.string());
    }
  }
  return session;
}

}  // namespace ballsight
