#pragma once
// A DDS domain of a test's own: loopback only (127.0.0.1, no multicast, no shared memory), a
// random domain id and a random namespace, so that tests running side by side never hear each
// other.

#include <random>
#include <string>

#include "ballsight/dds/domain.hpp"
#include "ballsight/service/navigation_hub.hpp"

namespace ballsight::test {

inline dds::DomainOptions test_domain() {
  std::random_device random;
  dds::DomainOptions options;
  options.domain = 100 + static_cast<int>(random() % 130);
  options.loopback = true;
  options.ns = "t" + random_hex(8);
  return options;
}

}  // namespace ballsight::test
