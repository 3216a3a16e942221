// The HTML report step (`ncverify report`, and the page `run` writes): the verification
// report of one or both directions as one self-contained page (render/html_report.hpp), each
// direction coloured as colorize colours it.
#pragma once

#include <string>
#include <vector>

#include "runners/colorize_runner.hpp"
#include "runners/report_runner.hpp"

namespace ncv {

// `colors` gives the map and its range (its tolerance is the report's).
std::string html_page(const VerificationReport& report, const ColorizeOptions& colors);

// `ncverify report DIST [REVERSE_DIST] -o PAGE.html`.
struct HtmlJob {
  // A part's distance files: one per direction, or every shard of a direction's job.
  std::vector<std::string> distances;
  std::string samples;  // the samples file of a single distance file, when not beside it
  std::string output;
  ReportOptions options;
  ColorizeOptions colors;
  ReportFiles files;         // empty paths: none
  std::string command_line;  // for the page's traceability
};
// The exit status: 0 within tolerance or without one, 1 out of tolerance.
int run_html_report(const HtmlJob& job);

}  // namespace ncv
