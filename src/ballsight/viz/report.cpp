#include "ballsight/viz/report.hpp"

#include <sstream>

namespace ballsight {

std::string html_report(const std::string& title, const std::vector<ReportSection>& sections) {
  std::ostringstream html;
  html << "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" << title
       << "</title>\n<style>body{font-family:sans-serif;max-width:1400px;margin:2em auto;}"
          ".grid{display:grid;grid-template-columns:repeat(auto-fill,minmax(320px,1fr));gap:1em}"
          "img{width:100%;border:1px solid #ccc}figcaption{font-size:0.85em}</style></head>"
          "<body>\n<h1>"
       << title << "</h1>\n";
  for (const ReportSection& s : sections) {
    html << "<h2>" << s.title << "</h2>\n<p>" << s.intro << "</p>\n<div class=\"grid\">\n";
    for (const ReportFigure& f : s.figures) {
      html << "<figure><a href=\"" << f.image << "\"><img src=\"" << f.image << "\" alt=\""
           << f.image << "\"></a><figcaption>" << f.image << ": " << f.caption
           << "</figcaption></figure>\n";
    }
    html << "</div>\n";
  }
  html << "</body></html>\n";
  return html.str();
}

std::string markdown_report(const std::string& title, const std::vector<ReportSection>& sections) {
  std::ostringstream md;
  md << "# " << title << "\n\n";
  for (const ReportSection& s : sections) {
    md << "## " << s.title << "\n\n" << s.intro << "\n\n";
    for (const ReportFigure& f : s.figures) md << "- `" << f.image << "`: " << f.caption << "\n";
    md << "\n";
  }
  return md.str();
}

}  // namespace ballsight
