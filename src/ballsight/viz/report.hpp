#pragma once
// The reports a person reads (`ballsight demo`'s report.html and report.md): the result first, a
// table and a picture, then sections of tables and figures, each figure a thumbnail that opens
// its picture. The HTML page carries its own style (the web pages' style sheet and the report's)
// and any script inline, so that it reads from its folder with no server. The text is written
// as given: titles, intros and captions are the report's own (an intro may hold HTML); table
// cells are text and are escaped.

#include <string>
#include <vector>

namespace ballsight {

/// One report row: a picture (path relative to the report) and what it shows.
struct ReportFigure {
  std::string image;
  std::string caption;
};

/// A table of text cells under a caption; `header` names the columns.
struct ReportTable {
  std::string caption;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

struct ReportSection {
  std::string title;
  std::string intro;  // HTML
  std::string live;   // HTML right below the intro: a figure of the page's own (a replay)
  std::vector<ReportTable> tables;
  std::vector<ReportFigure> figures;
  std::string after;  // HTML below the figures
};

struct ReportPage {
  std::string title;
  ReportSection result;  // what the report opens with
  std::vector<ReportSection> sections;
  std::string style;   // CSS of the page (the web pages' style sheet), inlined
  std::string script;  // a module script run once the page is read (empty: none), inlined
};

/// A complete HTML page: the title, the result, then each section (its intro, tables, figures
/// in a grid of thumbnails that open their pictures, and what follows them).
std::string html_report(const ReportPage& page);
/// The same in Markdown: tables as Markdown tables, figures as a list of paths and captions.
std::string markdown_report(const ReportPage& page);

/// `text` with &, <, > and " as HTML entities.
std::string html_escaped(const std::string& text);

}  // namespace ballsight
