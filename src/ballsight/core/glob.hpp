#pragma once
// File-name wildcards as a shell expands them, for `--images 'calib/left*.jpg'`: `*` matches any
// run of characters and `?` one character, in the last path component only.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ballsight {

/// Whether `name` matches `pattern` (`*` and `?`; every other character stands for itself).
bool wildcard_match(std::string_view pattern, std::string_view name);

/// Regular files in the pattern's folder whose names match its last component, sorted by name.
/// A pattern without wildcards names one file. Throws InputError naming the pattern when the
/// folder does not exist or nothing matches.
std::vector<std::filesystem::path> glob_files(const std::string& pattern);

}  // namespace ballsight
