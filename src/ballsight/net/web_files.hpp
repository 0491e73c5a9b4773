#pragma once
// The web pages `ballsight serve` serves beside API v1 (web/ in the source tree,
// docs/web-pages.md): GET / is the dashboard, GET /web/<file> any file of the folder. Only files
// of the kinds a page is made of (HTML, JavaScript, CSS, SVG, PNG, JSON) are served, only from
// inside the folder (no "..", no links out of it), and none larger than a few MiB. The pages'
// libraries come from npm (scripts/setup installs them into node_modules/, never into the tree):
// GET /web/vendor/<file> serves the few files of them the pages import, by name.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include "ballsight/net/api.hpp"

namespace ballsight {

class WebFiles {
 public:
  static constexpr std::size_t kMaxFileBytes = 4 * 1024 * 1024;

  /// Serves the files under `root`, and the pages' libraries from the npm folder `node_modules`
  /// (empty: none; a library missing there is a 404 saying so). Throws InputError naming `root`
  /// when it is not a folder with an index.html.
  explicit WebFiles(const std::filesystem::path& root,
                    const std::filesystem::path& node_modules = {});

  /// Whether `path` (no query) is a page's, not the API's: "/" (the dashboard),
  /// "/omni-calibration" and "/web/...".
  static bool is_page_path(const std::string& path);
  /// The file for a GET of `path`: 200 with its content type, or 404 naming the path.
  ApiResponse get(const std::string& path) const;

  const std::filesystem::path& root() const { return root_; }

 private:
  std::filesystem::path root_;  // canonical
  std::filesystem::path node_modules_;
};

}  // namespace ballsight
