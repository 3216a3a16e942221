#include "report_options.hpp"

#include <sstream>

#include "option_checks.hpp"
#include "render/svg_histogram.hpp"
#include "util/output_file.hpp"

namespace ncv::cmd {

void add_report_options(CLI::App& sub, ReportOptions& options) {
  sub.add_option("-t,--tol", options.tolerance,
                 "Tolerance zone LOWER:UPPER (e.g. -0.05:0.1), or T for ±T; out of it, exit 1")
      ->check(valid_zone());
  sub.add_option("--bins", options.bins, "Histogram bins")->capture_default_str();
  sub.add_option("--histogram-range", options.range,
                 "Histogram range LO:HI (default: d_min to d_max)")
      ->check(valid_range());
  sub.add_option("--regions", options.regions, "Out-of-tolerance regions listed")
      ->capture_default_str();
  sub.add_option("--histogram-svg", options.histogram_svg,
                 "Also draw the area-weighted histogram as SVG");
}

std::optional<Tolerance> parse_tolerance_option(const std::string& text) {
  if (text.empty()) return std::nullopt;
  return parse_tolerance(text);
}

PartReport make_report(const DistanceSet& distances, const ReportOptions& options) {
  HistogramOptions histogram;
  histogram.bins = options.bins;
  if (!options.range.empty()) {
    histogram.range = parse_value_range(options.range);
  }
  PartReport report =
      make_part_report(distances, parse_tolerance_option(options.tolerance), histogram);
  report.listed_regions = options.regions;
  return report;
}

void write_histogram(const PartReport& report, OutputFile& out) {
  std::ostringstream svg;
  write_histogram_svg(svg, report.statistics.histogram,
                      report.statistics.tolerance
                          ? std::optional<Tolerance>(report.statistics.tolerance->tolerance)
                          : std::nullopt);
  out.write(svg.str());
}

void write_histogram_if_asked(const PartReport& report, const ReportOptions& options) {
  if (options.histogram_svg.empty()) return;
  OutputFile out(options.histogram_svg, OutputKind::text);
  write_histogram(report, out);
  out.commit();
}

}  // namespace ncv::cmd
