#include "ballsight/core/utc_clock.hpp"

namespace ballsight {

std::int64_t utc_now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

std::int64_t utc_ns_of(std::chrono::steady_clock::time_point t) {
  return utc_now_ns() -
         std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - t)
             .count();
}

}  // namespace ballsight
