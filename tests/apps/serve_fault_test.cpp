// Fault: `ballsight serve --sim` killed (SIGKILL, no goodbye) and started again on the same port
// while the robot's client runs. The client notices, reconnects with back-off, follows the new
// run of the service from its latest update, and keeps acknowledging.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "ballsight/core/file_io.hpp"
#include "ballsight/net/http_robot_link.hpp"
#include "serve_process.hpp"
#include "temp_dir.hpp"

namespace ballsight::test {
namespace {

using std::chrono::milliseconds;

std::vector<std::string> serve_args(const std::string& listen, const std::string& token_file) {
  return {"--sim",      "--listen",   listen, "--rate",       "10",
          "--realtime", "--duration", "60",   "--token-file", token_file};
}

/// The next update newer than `seq` of the run `service`, waiting up to 30 s.
std::optional<LinkUpdate> next_of(RobotLink& link, const std::string& service) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (std::chrono::steady_clock::now() < deadline) {
    std::optional<LinkUpdate> u = link.next(milliseconds(1000));
    if (u && (service.empty() || u->service_id == service)) return u;
  }
  return std::nullopt;
}

TEST(ServeFault, TheRobotsClientOutlivesAKilledService) {
  const TempDir temp;
  const std::string token_file = (temp / "token").string();
  auto service = std::make_unique<ServeProcess>(serve_args("127.0.0.1:0", token_file));
  const unsigned short port = service->port();
  ASSERT_NE(port, 0);
  RobotLinkOptions options;
  options.port = port;
  options.token = read_file(token_file).substr(0, 32);
  options.backoff = {milliseconds(50), milliseconds(500), 2.0};
  HttpRobotLink link(options);
  std::optional<LinkUpdate> before = next_of(link, "");
  ASSERT_TRUE(before);
  std::uint64_t seq = before->seq;
  for (int k = 0; k < 3; ++k) {  // in order, acknowledged
    const std::optional<LinkUpdate> u = next_of(link, before->service_id);
    ASSERT_TRUE(u);
    EXPECT_EQ(u->seq, seq + 1);
    seq = u->seq;
    EXPECT_TRUE(link.acknowledge(seq)) << link.status().last_error;
  }

  service->kill(SIGKILL);
  service =
      std::make_unique<ServeProcess>(serve_args("127.0.0.1:" + std::to_string(port), token_file));
  ASSERT_EQ(service->port(), port);
  std::optional<LinkUpdate> after;
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while ((after = next_of(link, "")) && after->service_id == before->service_id &&
         std::chrono::steady_clock::now() < until) {
  }
  ASSERT_TRUE(after) << link.status().last_error;
  ASSERT_NE(after->service_id, before->service_id) << "no update of the restarted service in 60 s";
  EXPECT_GE(link.status().reconnects, 1);
  // Followed from the new run's latest update, then on without a gap.
  const std::optional<LinkUpdate> then = next_of(link, after->service_id);
  ASSERT_TRUE(then);
  EXPECT_EQ(then->seq, after->seq + 1);
  EXPECT_TRUE(link.acknowledge(then->seq)) << link.status().last_error;
  EXPECT_TRUE(link.status().connected);
}

}  // namespace
}  // namespace ballsight::test
