#include "ballsight/net/web_files.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "ballsight/core/error.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

struct Pages {
  test::TempDir temp;
  fs::path root = temp / "web";
  Pages() {
    write(root / "index.html", "<!doctype html>");
    write(root / "omni-calibration.html", "<!doctype html><title>omni</title>");
    write(root / "js" / "page.js", "export {};");
    write(root / "notes.txt", "not a page's file");
    write(temp / "secret.json", "{\"token\": 1}");
    fs::create_symlink(temp / "secret.json", root / "link.json");
  }
};

TEST(WebFiles, ServesThePagesWithTheirTypes) {
  Pages p;
  const WebFiles files(p.root);
  const ApiResponse index = files.get("/");
  EXPECT_EQ(index.status, 200);
  EXPECT_EQ(index.body, "<!doctype html>");
  EXPECT_EQ(index.content_type, "text/html; charset=utf-8");
  const ApiResponse js = files.get("/web/js/page.js");
  EXPECT_EQ(js.status, 200);
  EXPECT_EQ(js.content_type, "text/javascript; charset=utf-8");
  EXPECT_TRUE(WebFiles::is_page_path("/"));
  EXPECT_TRUE(WebFiles::is_page_path("/web/x.js"));
  EXPECT_TRUE(WebFiles::is_page_path("/omni-calibration"));
  EXPECT_EQ(files.get("/omni-calibration").body, "<!doctype html><title>omni</title>");
  EXPECT_FALSE(WebFiles::is_page_path("/omni-calibration/x"));
  EXPECT_FALSE(WebFiles::is_page_path("/api/v1/site"));
}

// Nothing outside the folder, nothing that is not a page's kind of file, nothing missing.
TEST(WebFiles, RefusesWhatIsNotAPageOfTheFolder) {
  Pages p;
  const WebFiles files(p.root);
  for (const char* path :
       {"/web/../secret.json", "/web/js/../../secret.json", "/web//etc/passwd", "/web/link.json",
        "/web/notes.txt", "/web/none.js", "/web/", "/web/js"}) {
    const ApiResponse r = files.get(path);
    EXPECT_EQ(r.status, 404) << path;
    EXPECT_NE(r.body.find("no such page"), std::string::npos) << path;
    EXPECT_EQ(r.body.find("token"), std::string::npos) << path;
  }
}

// The pages' libraries come from the npm folder, only the files the pages import, by name.
TEST(WebFiles, TheLibrariesFromNpmByName) {
  Pages p;
  const fs::path npm = p.temp / "node_modules";
  fs::create_directories(npm / "uplot" / "dist");
  write(npm / "uplot" / "dist" / "uPlot.esm.js", "export default 1;");
  write(npm / "uplot" / "dist" / "uPlot.cjs.js", "module.exports = 1;");
  const WebFiles files(p.root, npm);
  const ApiResponse lib = files.get("/web/vendor/uplot/uPlot.esm.js");
  EXPECT_EQ(lib.status, 200);
  EXPECT_EQ(lib.body, "export default 1;");
  EXPECT_EQ(lib.content_type, "text/javascript; charset=utf-8");
  EXPECT_EQ(files.get("/web/vendor/uplot/uPlot.cjs.js").status, 404);  // not one the pages use
  EXPECT_EQ(files.get("/web/vendor/../node_modules/uplot/dist/uPlot.esm.js").status, 404);
  const ApiResponse css = files.get("/web/vendor/uplot/uPlot.min.css");  // not installed
  EXPECT_EQ(css.status, 404);
  EXPECT_NE(css.body.find("scripts/setup"), std::string::npos) << css.body;
  EXPECT_EQ(WebFiles(p.root).get("/web/vendor/uplot/uPlot.esm.js").status, 404);
}

TEST(WebFiles, AFolderWithoutPagesIsAnError) {
  test::TempDir temp;
  EXPECT_THROW(WebFiles(temp / "missing"), InputError);
  try {
    WebFiles files{temp.path()};
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("index.html"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ballsight
