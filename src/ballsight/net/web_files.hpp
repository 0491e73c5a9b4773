#pragma once
// The web pages `ballsight serve` serves beside API v1 (web/ in the source tree,
// docs/web-pages.md): GET / is the dashboard, GET /web/<file> any file of the folder. Only files
// of the kinds a page is made of (HTML, JavaScript, CSS, SVG, PNG, JSON) are served, only from
// inside the folder (no "..", no links out of it), and none larger than a few MiB.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include "ballsight/net/api.hpp"

namespace ballsight {

class WebFiles {
 public:
  static constexpr std::size_t kMaxFileBytes = 4 * 1024 * 1024;

  /// Serves the files under `root`. Throws InputError naming it when it is not a folder with an
  /// index.html.
  explicit WebFiles(const std::filesystem::path& root);

  /// Whether `path` (no query) is a page's, not the API's: "/" (the dashboard),
  /// "/omni-calibration" and "/web/...".
  static bool is_page_path(const std::string& path);
  /// The file for a GET of `path`: 200 with its content type, or 404 naming the path.
  ApiResponse get(const std::string& path) const;

  const std::filesystem::path& root() const { return root_; }

 private:
  std::filesystem::path root_;  // canonical
};

}  // namespace ballsight
