#include "runners/report_runner.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <sstream>

#include <tbb/parallel_invoke.h>

#include "files/distance_job.hpp"
#include "render/svg_histogram.hpp"
#include "util/error.hpp"
#include "util/input_bytes.hpp"
#include "util/output_file.hpp"
#include "util/stopwatch.hpp"
#include "util/timestamp.hpp"

namespace ncv {

PartReport make_report(const DistanceSet& distances, const ReportOptions& options) {
  PartReport report = make_part_report(distances, options.tolerance, options.histogram);
  report.listed_regions = options.regions;
  report.units = options.units;
  return report;
}

Traceability traceability(const std::string& command_line) {
  Traceability trace;
  trace.date = report_timestamp();
  trace.command_line = command_line;
  return trace;
}

VerificationReport make_verification_report(const DistanceSet& main, const DistanceSet* reverse,
                                            const ReportOptions& options) {
  // The two directions are independent: made side by side.
  VerificationReport report;
  report.one_sided = options.one_sided;
  tbb::parallel_invoke([&] { report.main = make_report(main, options); },
                       [&] {
                         if (reverse) report.reverse = make_report(*reverse, options);
                       });
  return report;
}

std::string histogram_svg(const PartReport& report) {
  std::ostringstream svg;
  const std::optional<ToleranceAreas>& tolerance = report.statistics.tolerance;
  write_histogram_svg(svg, report.statistics.histogram,
                      tolerance ? std::optional<Tolerance>(tolerance->tolerance) : std::nullopt,
                      picture_text(report));
  return svg.str();
}

std::deque<OutputFile> write_report_files(const PartReport& report, const ReportFiles& files) {
  std::deque<OutputFile> outputs;
  if (!files.histogram_svg.empty()) {
    outputs.emplace_back(files.histogram_svg, OutputKind::text).write(histogram_svg(report));
  }
  if (!files.regions_csv.empty()) {
    outputs.emplace_back(files.regions_csv, OutputKind::text).write(regions_csv(report));
  }
  if (!files.histogram_csv.empty()) {
    outputs.emplace_back(files.histogram_csv, OutputKind::text).write(histogram_csv(report));
  }
  return outputs;
}

int run_stats(const StatsJob& job) {
  if (job.csv_header_only) {
    OutputFile out(job.output, OutputKind::text);
    out.write(report_csv_header());
    out.commit();
    return 0;
  }
  return write_part_report(job.distances, job.samples, job.options, job.command_line, job.output,
                           job.files, [&job](const VerificationReport& report) {
                             return format_report(report, job.format, job.csv_header);
                           });
}

int write_part_report(const std::vector<std::string>& distances, const std::string& samples,
                      const ReportOptions& options, const std::string& command_line,
                      const std::string& output, const ReportFiles& files,
                      const std::function<std::string(const VerificationReport&)>& format) {
  Stopwatch clock;
  const PartDistances part = read_part_distances(distances, samples);
  spdlog::debug("read the distances in {:.3f} s", clock.seconds());
  clock.restart();
  VerificationReport report =
      make_verification_report(part.main, part.reverse ? &*part.reverse : nullptr, options);
  report.trace = traceability(command_line);
  spdlog::debug("statistics, histogram, percentiles and regions in {:.3f} s", clock.seconds());
  // Every output open before any is committed: a histogram path that cannot be written
  // leaves no report either.
  OutputFile out(output, OutputKind::text);
  std::deque<OutputFile> extras = write_report_files(report.main, files);
  out.write(format(report));
  out.commit();
  for (OutputFile& extra : extras) extra.commit();
  return verdict_status(report);
}

}  // namespace ncv
