#include "runners/report_runner.hpp"

#include <fmt/format.h>

#include <sstream>

#include "files/distance_job.hpp"
#include "render/svg_histogram.hpp"
#include "util/error.hpp"
#include "util/input_bytes.hpp"
#include "util/output_file.hpp"

namespace ncv {
PartReport make_report(const DistanceSet& distances, const ReportOptions& options) {
  PartReport report = make_part_report(distances, options.tolerance, options.histogram);
  report.listed_regions = options.regions;
  return report;
}

VerificationReport make_verification_report(const DistanceSet& main, const DistanceSet* reverse,
                                            const ReportOptions& options) {
  VerificationReport report{make_report(main, options), std::nullopt};
  if (reverse) report.reverse = make_report(*reverse, options);
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
  const PartDistances part = read_part_distances(job.distances, job.samples);
  const VerificationReport report =
      make_verification_report(part.main, part.reverse ? &*part.reverse : nullptr, job.options);
  // Both outputs open before either is committed: a histogram path that cannot be
  // written leaves no report either.
  OutputFile out(job.output, OutputKind::text);
  std::optional<OutputFile> histogram;
  if (!job.histogram_svg.empty()) {
    histogram.emplace(job.histogram_svg, OutputKind::text);
    histogram->write(histogram_svg(report.main));
  }
  out.write(format_report(report, job.format, job.csv_header));
  out.commit();
  if (histogram) histogram->commit();
  return verdict_status(report);
}

}  // namespace ncv
