#include "ballsight/net/bearer_token.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/service/navigation_hub.hpp"

namespace ballsight {

std::string read_or_create_token(const std::filesystem::path& file) {
  namespace fs = std::filesystem;
  if (fs::exists(file)) {
    std::string text = read_file(file);
    text = text.substr(0, text.find_first_of("\r\n"));
    require(text.size() >= 16, file.string(), "the token must be at least 16 characters");
    return text;
  }
  // Private from its first byte: created 0600, never there with wider rights.
  const std::string token = random_hex(32) + "\n";
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  require(fd >= 0, file.string(), std::string("cannot create it: ") + std::strerror(errno));
  const bool written =
      ::write(fd, token.data(), token.size()) == static_cast<ssize_t>(token.size());
  require(::close(fd) == 0 && written, file.string(), "cannot write the token");
  return token.substr(0, 32);
}

bool shows_token(std::string_view authorization, const std::string& token) {
  const std::string expected = "Bearer " + token;
  if (authorization.size() != expected.size()) return false;
  unsigned char diff = 0;
  for (std::size_t i = 0; i < expected.size(); ++i)
    diff |= static_cast<unsigned char>(authorization[i] ^ expected[i]);
  return diff == 0;
}

}  // namespace ballsight
