#include "ballsight/core/glob.hpp"

#include <algorithm>

#include "ballsight/core/error.hpp"

namespace ballsight {

namespace fs = std::filesystem;

bool wildcard_match(std::string_view pattern, std::string_view name) {
  // Greedy matching with backtracking to the last `*`: linear in practice, no recursion.
  std::size_t p = 0, n = 0, star = std::string_view::npos, resume = 0;
  while (n < name.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == name[n])) {
      ++p;
      ++n;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      resume = n;
    } else if (star != std::string_view::npos) {
      p = star + 1;
      n = ++resume;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

std::vector<fs::path> glob_files(const std::string& pattern) {
  const fs::path full(pattern);
  const std::string name = full.filename().string();
  const fs::path dir = full.has_parent_path() ? full.parent_path() : fs::path(".");
  require(!name.empty(), pattern, "expected a file name pattern, e.g. 'images/left*.jpg'");
  require(dir.string().find_first_of("*?") == std::string::npos, pattern,
          "wildcards are allowed in the file name only");
  std::error_code ec;
  require(fs::is_directory(dir, ec), pattern, "folder " + dir.string() + " does not exist");
  std::vector<fs::path> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
    if (entry.is_regular_file(ec) && wildcard_match(name, entry.path().filename().string())) {
      files.push_back(full.has_parent_path() ? entry.path() : entry.path().filename());
    }
  }
  require(!ec, pattern, "cannot list folder " + dir.string());
  require(!files.empty(), pattern, "no file matches");
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace ballsight
