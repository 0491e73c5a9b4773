#pragma once
// Times that travel between processes and machines are UTC nanoseconds since the epoch (a ROS 2
// header's stamp, an update's capture time); times inside a process are std::chrono::steady_clock
// (a capture thread's receipt of a frame), which does not jump.

#include <chrono>
#include <cstdint>

namespace ballsight {

/// UTC now, nanoseconds since the epoch.
std::int64_t utc_now_ns();

/// The UTC time of `t` on the steady clock: now less how long ago `t` was.
std::int64_t utc_ns_of(std::chrono::steady_clock::time_point t);

}  // namespace ballsight
