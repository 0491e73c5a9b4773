#include "ballsight/world/world_model.hpp"

#include <string>

#include "ballsight/core/error.hpp"

namespace ballsight {

void require_list_per_camera(std::size_t cameras, std::size_t lists, const char* where) {
  require(cameras == lists, where,
          "need one detection list per camera (" + std::to_string(cameras) + " cameras, " +
              std::to_string(lists) + " lists)");
}

}  // namespace ballsight
