// Options of the report (stats and run): tolerance, histogram, regions.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "statistics/statistics_report.hpp"
#include "util/output_file.hpp"

namespace ncv::cmd {

struct ReportOptions {
  std::string tolerance;  // "lower:upper" or "t" for ±t; empty = none
  std::uint32_t bins = 64;
  std::string range;          // histogram range "lo:hi"; empty = [d_min, d_max]
  std::size_t regions = 20;   // regions listed
  std::string histogram_svg;  // where to draw the histogram; empty = nowhere
};

void add_report_options(CLI::App& sub, ReportOptions& options);
std::optional<Tolerance> parse_tolerance_option(const std::string& text);
PartReport make_report(const DistanceSet& distances, const ReportOptions& options);
void write_histogram_if_asked(const PartReport& report, const ReportOptions& options);
// The histogram SVG to an output the caller opened together with its others, so that a
// path that cannot be written leaves none of them behind.
void write_histogram(const PartReport& report, OutputFile& out);

}  // namespace ncv::cmd
