#include "ballsight/viz/report.hpp"

#include <sstream>

namespace ballsight {
namespace {

// The report's own layout over the web pages' style sheet: readable columns at 1280 px, one
// column on a tablet held upright.
constexpr const char* kReportStyle = R"(
main.report { display: block; max-width: 1240px; margin: 0 auto; padding: 1rem; }
main.report > section { margin: 0 0 1.2rem; padding: 0.8rem 1rem; }
main.report h2 { font-size: 1.15rem; margin: 0 0 0.6rem; }
main.report p { line-height: 1.45; max-width: 75ch; }
table { border-collapse: collapse; margin: 0.6rem 0 1rem; font-variant-numeric: tabular-nums; }
table caption { caption-side: top; text-align: left; font-size: 0.85rem; color: #4a554f;
                padding-bottom: 0.3rem; }
th, td { border-bottom: 1px solid #d5ddd7; padding: 0.25rem 0.7rem; text-align: left; }
th { background: #e4ece6; font-weight: 600; }
.table-scroll { overflow-x: auto; }
.thumbs { display: grid; grid-template-columns: repeat(auto-fill, minmax(260px, 1fr));
          gap: 0.8rem; }
.thumbs figure { margin: 0; }
.thumbs img { width: 100%; height: auto; border: 1px solid #c9d3cc; border-radius: 3px; }
#result .thumbs { grid-template-columns: minmax(0, 900px); }
pre { overflow-x: auto; background: #f8faf8; padding: 0.5rem; font-size: 0.8rem; }
.replay .controls { display: flex; flex-wrap: wrap; gap: 0.6rem; align-items: center;
                    margin-bottom: 0.5rem; }
.replay input[type=range] { flex: 1 1 300px; }
.replay canvas { width: 100%; max-width: 1000px; height: auto; border-radius: 4px;
                 background: #3a5a47; }
)";

void table_html(std::ostringstream& html, const ReportTable& t) {
  html << "<div class=\"table-scroll\"><table>";
  if (!t.caption.empty()) html << "<caption>" << html_escaped(t.caption) << "</caption>";
  html << "<thead><tr>";
  for (const std::string& h : t.header) html << "<th>" << html_escaped(h) << "</th>";
  html << "</tr></thead><tbody>\n";
  for (const std::vector<std::string>& row : t.rows) {
    html << "<tr>";
    for (const std::string& cell : row) html << "<td>" << html_escaped(cell) << "</td>";
    html << "</tr>\n";
  }
  html << "</tbody></table></div>\n";
}

void section_html(std::ostringstream& html, const ReportSection& s, const std::string& id) {
  html << "<section" << (id.empty() ? "" : " id=\"" + id + "\"") << ">\n<h2>" << s.title
       << "</h2>\n";
  if (!s.intro.empty()) html << "<p>" << s.intro << "</p>\n";
  html << s.live;
  for (const ReportTable& t : s.tables) table_html(html, t);
  if (!s.figures.empty()) {
    html << "<div class=\"thumbs\">\n";
    for (const ReportFigure& f : s.figures) {
      html << "<figure><a href=\"" << f.image << "\"><img src=\"" << f.image << "\" alt=\""
           << html_escaped(f.caption) << "\" loading=\"lazy\"></a><figcaption>"
           << html_escaped(f.caption) << "</figcaption></figure>\n";
    }
    html << "</div>\n";
  }
  html << s.after << "</section>\n";
}

void table_markdown(std::ostringstream& md, const ReportTable& t) {
  if (!t.caption.empty()) md << t.caption << "\n\n";
  md << "|";
  for (const std::string& h : t.header) md << " " << h << " |";
  md << "\n|";
  for (std::size_t i = 0; i < t.header.size(); ++i) md << "---|";
  md << "\n";
  for (const std::vector<std::string>& row : t.rows) {
    md << "|";
    for (const std::string& cell : row) md << " " << cell << " |";
    md << "\n";
  }
  md << "\n";
}

void section_markdown(std::ostringstream& md, const ReportSection& s) {
  md << "## " << s.title << "\n\n";
  if (!s.intro.empty()) md << s.intro << "\n\n";
  for (const ReportTable& t : s.tables) table_markdown(md, t);
  for (const ReportFigure& f : s.figures) md << "- `" << f.image << "`: " << f.caption << "\n";
  if (!s.figures.empty()) md << "\n";
  if (!s.after.empty()) md << s.after << "\n\n";
}

}  // namespace

std::string html_escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string html_report(const ReportPage& page) {
  std::ostringstream html;
  html << "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
          "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"><title>"
       << page.title << "</title>\n<style>" << page.style << kReportStyle
       << "</style></head>\n<body>\n<header><h1>" << page.title
       << "</h1></header>\n<main class=\"report\">\n";
  section_html(html, page.result, "result");
  for (const ReportSection& s : page.sections) section_html(html, s, "");
  html << "</main>\n";
  if (!page.script.empty()) html << "<script type=\"module\">\n" << page.script << "</script>\n";
  html << "</body></html>\n";
  return html.str();
}

std::string markdown_report(const ReportPage& page) {
  std::ostringstream md;
  md << "# " << page.title << "\n\n";
  section_markdown(md, page.result);
  for (const ReportSection& s : page.sections) section_markdown(md, s);
  return md.str();
}

}  // namespace ballsight
