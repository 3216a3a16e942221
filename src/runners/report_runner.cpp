#include "runners/report_runner.hpp"

#include <sstream>

#include "render/svg_histogram.hpp"
#include "util/output_file.hpp"

namespace ncv {

PartReport make_report(const DistanceSet& distances, const ReportOptions& options) {
  PartReport report = make_part_report(distances, options.tolerance, options.histogram);
  report.listed_regions = options.regions;
  return report;
}

std::string histogram_svg(const PartReport& report) {
  std::ostringstream svg;
  const std::optional<ToleranceAreas>& tolerance = report.statistics.tolerance;
  write_histogram_svg(svg, report.statistics.histogram,
                      tolerance ? std::optional<Tolerance>(tolerance->tolerance) : std::nullopt);
  return svg.str();
}

int run_stats(const StatsJob& job) {
  if (job.csv_header_only) {
    OutputFile out(job.output, OutputKind::text);
    out.write(report_csv_header());
    out.commit();
    return 0;
  }
  const DistanceSet distances = read_distance_file(job.distances);
  const PartReport report = make_report(distances, job.options);
  // Both outputs open before either is committed: a histogram path that cannot be
  // written leaves no report either.
  OutputFile out(job.output, OutputKind::text);
  std::optional<OutputFile> histogram;
  if (!job.histogram_svg.empty()) {
    histogram.emplace(job.histogram_svg, OutputKind::text);
    histogram->write(histogram_svg(report));
  }
  out.write(format_report(report, job.format, job.csv_header));
  out.commit();
  if (histogram) histogram->commit();
  return verdict_status(report);
}

}  // namespace ncv
