#include "runners/report_runner.hpp"

#include <fmt/format.h>

#include <sstream>

#include "render/svg_histogram.hpp"
#include "util/error.hpp"
#include "util/input_bytes.hpp"
#include "util/output_file.hpp"
#include "util/timestamp.hpp"

namespace ncv {

DistanceFiles read_distance_files(const std::vector<std::string>& paths) {
  if (paths.empty() || paths.size() > 2) {
    throw UsageError("stats: give one distance file, or a forward and a reverse one");
  }
  DistanceFiles files;
  files.main = read_distance_file(paths[0]);
  if (paths.size() == 1) return files;
  files.reverse = read_distance_file(paths[1]);
  if (files.main->direction == files.reverse->direction) {
    throw UsageError(fmt::format("{} and {} both measure the {} direction; give one of each",
                                 input_name(paths[0]), input_name(paths[1]),
                                 name_of(kDirectionNames, files.main->direction)));
  }
  std::string main_path = paths[0], reverse_path = paths[1];
  if (files.main->direction == Direction::reverse) {
    std::swap(files.main, files.reverse);
    std::swap(main_path, reverse_path);
  }
  check_same_part(*files.main, input_name(main_path), *files.reverse, input_name(reverse_path));
  return files;
}

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
  VerificationReport report{make_report(main, options), std::nullopt, {}};
  if (reverse) report.reverse = make_report(*reverse, options);
  return report;
}

void check_same_part(const DistanceSet& forward, const std::string& forward_source,
                     const DistanceSet& reverse, const std::string& reverse_source) {
  if (forward.samples.mesh_hash != reverse.reference.hash ||
      forward.reference.hash != reverse.samples.mesh_hash) {
    throw UsageError(fmt::format(
        "{} and {} do not measure the same part: the forward file compares {} with {}, the "
        "reverse one {} with {}",
        forward_source, reverse_source, forward.samples.source, forward.reference.source,
        reverse.samples.source, reverse.reference.source));
  }
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
  const DistanceFiles files = read_distance_files(job.distances);
  VerificationReport report =
      make_verification_report(*files.main, files.reverse ? &*files.reverse : nullptr, job.options);
  report.trace = traceability(job.command_line);
  // Every output open before any is committed: a histogram path that cannot be written
  // leaves no report either.
  OutputFile out(job.output, OutputKind::text);
  std::deque<OutputFile> extras = write_report_files(report.main, job.files);
  out.write(format_report(report, job.format, job.csv_header));
  out.commit();
  for (OutputFile& extra : extras) extra.commit();
  return verdict_status(report);
}

}  // namespace ncv
