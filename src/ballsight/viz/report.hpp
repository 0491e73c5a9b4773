#pragma once
// The reports a person reads (`ballsight demo`'s report.html and report.md): a title and sections
// of figures, each a picture with its caption. The text is written as given: titles, intros and
// captions are the report's own (an intro may hold HTML), not user input.

#include <string>
#include <vector>

namespace ballsight {

/// One report row: a picture (path relative to the report) and what it shows.
struct ReportFigure {
  std::string image;
  std::string caption;
};

struct ReportSection {
  std::string title;
  std::string intro;
  std::vector<ReportFigure> figures;
};

/// A complete HTML page: the title, then each section's intro and its figures in a grid, each
/// linking to its picture.
std::string html_report(const std::string& title, const std::vector<ReportSection>& sections);
/// The same in Markdown, the figures as a list of paths and captions.
std::string markdown_report(const std::string& title, const std::vector<ReportSection>& sections);

}  // namespace ballsight
