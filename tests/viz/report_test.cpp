#include "ballsight/viz/report.hpp"

#include <gtest/gtest.h>

namespace ballsight {
namespace {

const std::vector<ReportSection> kSections{
    {"First", "<b>intro</b> one", {{"a/one.png", "the first"}, {"a/two.png", "the second"}}},
    {"Second", "intro two", {}}};

TEST(Report, HtmlHasTheTitleThenEachSectionWithItsLinkedFigures) {
  const std::string html = html_report("Demo", kSections);
  EXPECT_TRUE(html.starts_with("<!doctype html>\n"));
  EXPECT_TRUE(html.ends_with("</body></html>\n"));
  const auto title = html.find("<h1>Demo</h1>");
  const auto first = html.find("<h2>First</h2>\n<p><b>intro</b> one</p>");
  const auto figure = html.find("<a href=\"a/two.png\"><img src=\"a/two.png\"");
  const auto second = html.find("<h2>Second</h2>");
  ASSERT_NE(title, std::string::npos);
  ASSERT_NE(first, std::string::npos);
  ASSERT_NE(figure, std::string::npos);
  ASSERT_NE(second, std::string::npos);
  EXPECT_LT(title, first);
  EXPECT_LT(first, figure);
  EXPECT_LT(figure, second);
  EXPECT_NE(html.find("<figcaption>a/one.png: the first</figcaption>"), std::string::npos);
}

TEST(Report, MarkdownListsEachSectionsFigures) {
  EXPECT_EQ(markdown_report("Demo", kSections),
            "# Demo\n\n"
            "## First\n\n<b>intro</b> one\n\n"
            "- `a/one.png`: the first\n- `a/two.png`: the second\n\n"
            "## Second\n\nintro two\n\n\n");
}

}  // namespace
}  // namespace ballsight
