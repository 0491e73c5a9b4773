#include "ballsight/core/file_io.hpp"

#include <fstream>
#include <system_error>

#include "ballsight/core/error.hpp"

namespace ballsight {

namespace fs = std::filesystem;

std::string read_file(const fs::path& path, std::uintmax_t max_bytes) {
  const auto too_large = [&](std::uintmax_t bytes) {
    return path.string() + ": " + std::to_string(bytes) +
           " bytes or more, larger than the limit of " + std::to_string(max_bytes) +
           " bytes; not read";
  };
  std::error_code ec;
  const bool regular = fs::is_regular_file(path, ec);
  const std::uintmax_t size = regular ? fs::file_size(path, ec) : 0;
  if (regular && !ec && size > max_bytes) throw InputError(too_large(size));
  std::ifstream in(path, std::ios::binary);
  require(in.good(), path.string(), "cannot open for reading");
  std::string bytes;
  if (regular && !ec) bytes.reserve(size);
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    const auto n = static_cast<std::size_t>(in.gcount());
    if (bytes.size() + n > max_bytes) throw InputError(too_large(bytes.size() + n));
    bytes.append(chunk, n);
  }
  require(!in.bad(), path.string(), "read failed");
  return bytes;
}

void write_file_atomic(const fs::path& path, std::string_view bytes) {
  const fs::path parent = path.has_parent_path() ? path.parent_path() : fs::path(".");
  require(fs::is_directory(parent), path.string(), "folder " + parent.string() + " does not exist");
  fs::path tmp = parent / path.filename();
  tmp += ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    require(out.good(), tmp.string(), "cannot open for writing");
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out.good()) {
      std::error_code ignored;
      fs::remove(tmp, ignored);
      throw InputError(path.string() + ": write failed");
    }
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw InputError(path.string() + ": cannot replace file (" + ec.message() + ")");
  }
}

void ensure_directory(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  require(!ec && fs::is_directory(dir), dir.string(), "cannot create output folder");
}

}  // namespace ballsight
