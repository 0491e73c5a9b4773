#include "ballsight/net/web_files.hpp"

#include <array>
#include <string_view>
#include <system_error>
#include <utility>

#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"

namespace ballsight {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kPagePrefix = "/web/";

constexpr std::array<std::pair<std::string_view, std::string_view>, 7> kContentTypes{{
    {".html", "text/html; charset=utf-8"},
    {".js", "text/javascript; charset=utf-8"},
    {".mjs", "text/javascript; charset=utf-8"},
    {".css", "text/css; charset=utf-8"},
    {".svg", "image/svg+xml"},
    {".png", "image/png"},
    {".json", "application/json"},
}};

/// The pages' own addresses and their files.
constexpr std::array<std::pair<std::string_view, std::string_view>, 3> kPages{{
    {"/", "index.html"},
    {"/omni-calibration", "omni-calibration.html"},
    {"/court-calibration", "court-calibration.html"},
}};

std::optional<std::string_view> page_file(const std::string& path) {
  for (const auto& [address, file] : kPages)
    if (path == address) return file;
  return std::nullopt;
}

/// The library files the pages import (/web/vendor/...) and where npm puts them.
constexpr std::array<std::pair<std::string_view, std::string_view>, 2> kVendorFiles{{
    {"/web/vendor/uplot/uPlot.esm.js", "uplot/dist/uPlot.esm.js"},
    {"/web/vendor/uplot/uPlot.min.css", "uplot/dist/uPlot.min.css"},
}};

std::optional<std::string_view> content_type(const fs::path& file) {
  const std::string extension = file.extension().string();
  for (const auto& [ext, type] : kContentTypes)
    if (extension == ext) return type;
  return std::nullopt;
}

}  // namespace

WebFiles::WebFiles(const fs::path& root, const fs::path& node_modules)
    : node_modules_(node_modules) {
  std::error_code ec;
  root_ = fs::canonical(root, ec);
  if (ec || !fs::is_directory(root_))
    throw InputError(root.string() + ": the web pages' folder does not exist");
  if (!fs::is_regular_file(root_ / "index.html"))
    throw InputError(root.string() + ": the web pages' folder has no index.html");
}

bool WebFiles::is_page_path(const std::string& path) {
  return page_file(path) || path.starts_with(kPagePrefix);
}

ApiResponse WebFiles::get(const std::string& path) const {
  for (const auto& [address, file] : kVendorFiles) {
    if (path != address) continue;
    std::error_code ec;
    if (node_modules_.empty() || !fs::is_regular_file(node_modules_ / file, ec)) {
      return api_error(404, "the pages' npm library is not installed (scripts/setup)", path);
    }
    ApiResponse response(200, read_file(node_modules_ / file));
    response.content_type = std::string(*content_type(fs::path(file)));
    return response;
  }
  const std::optional<std::string_view> page = page_file(path);
  const std::string relative =
      page ? std::string(*page) : path.substr(std::min(path.size(), kPagePrefix.size()));
  const fs::path requested = fs::path(relative).lexically_normal();
  const auto not_found = [&] { return api_error(404, "no such page", path); };
  if (relative.empty() || requested.is_absolute() || requested.empty() ||
      *requested.begin() == "..")
    return not_found();
  const std::optional<std::string_view> type = content_type(requested);
  if (!type) return not_found();
  std::error_code ec;
  const fs::path file = fs::canonical(root_ / requested, ec);
  if (ec || !fs::is_regular_file(file) || !file.string().starts_with(root_.string() + "/"))
    return not_found();
  if (fs::file_size(file, ec) > kMaxFileBytes || ec) return not_found();
  try {
    ApiResponse response(200, read_file(file));
    response.content_type = std::string(*type);
    return response;
  } catch (const InputError&) {
    return api_error(500, "cannot read the page", path);
  }
}

}  // namespace ballsight
