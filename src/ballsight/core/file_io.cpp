#include "ballsight/core/file_io.hpp"

#include <fstream>
#include <sstream>
#include <system_error>

#include "ballsight/core/error.hpp"

namespace ballsight {

namespace fs = std::filesystem;

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  require(in.good(), path.string(), "cannot open for reading");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  require(!in.bad(), path.string(), "read failed");
  return buffer.str();
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
