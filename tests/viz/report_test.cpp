#include "ballsight/viz/report.hpp"

#include <gtest/gtest.h>

namespace ballsight {
namespace {

ReportPage page() {
  ReportPage p;
  p.title = "Demo";
  p.style = "body{margin:0}";
  p.result = {"The result",
              "all <b>collected</b>",
              "",
              {{"", {"system", "balls"}, {{"a<b", "3"}}}},
              {{"a/map.png", "the map"}},
              ""};
  p.sections = {{"First",
                 "<b>intro</b> one",
                 "<canvas></canvas>",
                 {},
                 {{"a/one.png", "the first"}, {"a/two.png", "the \"2nd\""}},
                 "<pre>x</pre>"},
                {"Second", "intro two", "", {}, {}, ""}};
  return p;
}

TEST(Report, HtmlOpensWithTheResultThenEachSectionWithItsThumbnails) {
  const std::string html = html_report(page());
  EXPECT_TRUE(html.starts_with("<!doctype html>\n"));
  EXPECT_TRUE(html.ends_with("</body></html>\n"));
  EXPECT_NE(html.find("<meta name=\"viewport\""), std::string::npos) << "reads on a tablet";
  EXPECT_NE(html.find("<style>body{margin:0}"), std::string::npos) << "the pages' style, inlined";
  const auto title = html.find("<h1>Demo</h1>");
  const auto result = html.find("<section id=\"result\">\n<h2>The result</h2>");
  const auto table = html.find("<th>system</th><th>balls</th>");
  const auto first = html.find("<h2>First</h2>\n<p><b>intro</b> one</p>\n<canvas></canvas>");
  const auto figure = html.find("<a href=\"a/two.png\"><img src=\"a/two.png\"");
  const auto second = html.find("<h2>Second</h2>");
  for (const auto at : {title, result, table, first, figure, second})
    ASSERT_NE(at, std::string::npos) << html;
  EXPECT_LT(title, result);
  EXPECT_LT(table, first);
  EXPECT_LT(first, figure);
  EXPECT_LT(figure, second);
  EXPECT_NE(html.find("<td>a&lt;b</td><td>3</td>"), std::string::npos) << "cells are escaped";
  EXPECT_NE(html.find("<figcaption>the &quot;2nd&quot;</figcaption>"), std::string::npos);
  EXPECT_NE(html.find("</div>\n<pre>x</pre></section>"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos) << "no script given, none written";
  ReportPage scripted = page();
  scripted.script = "start();\n";
  EXPECT_NE(html_report(scripted).find("<script type=\"module\">\nstart();\n</script>"),
            std::string::npos);
}

TEST(Report, MarkdownHasTheTablesAndListsTheFigures) {
  EXPECT_EQ(markdown_report(page()),
            "# Demo\n\n"
            "## The result\n\nall <b>collected</b>\n\n"
            "| system | balls |\n|---|---|\n| a<b | 3 |\n\n"
            "- `a/map.png`: the map\n\n"
            "## First\n\n<b>intro</b> one\n\n"
            "- `a/one.png`: the first\n- `a/two.png`: the \"2nd\"\n\n<pre>x</pre>\n\n"
            "## Second\n\nintro two\n\n");
}

}  // namespace
}  // namespace ballsight
