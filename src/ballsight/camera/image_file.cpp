#include "ballsight/camera/image_file.hpp"

#include "ballsight/core/error.hpp"

namespace ballsight {

cv::Mat read_image(const std::filesystem::path& file, int flags) {
  std::error_code ec;
  require(std::filesystem::is_regular_file(file, ec), file.string(), "does not exist");
  cv::Mat image = cv::imread(file.string(), flags);
  require(!image.empty(), file.string(), "cannot read the image");
  return image;
}

}  // namespace ballsight
