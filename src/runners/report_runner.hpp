// The report step (`ncverify stats`, and run's stats phase): the error measures of a distance
// file (docs/METHOD.md "Error measures"), its verdict against a tolerance, the out-of-tolerance
// regions, as text, JSON or CSV, and the histogram as SVG.
#pragma once

#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "files/distance_file.hpp"
#include "statistics/area_histogram.hpp"
#include "statistics/statistics_report.hpp"
#include "statistics/tolerance.hpp"
#include "util/output_file.hpp"

namespace ncv {

struct ReportOptions {
  std::optional<Tolerance> tolerance;  // none: no verdict, no regions
  HistogramOptions histogram;          // 64 bins over [d_min, d_max] unless given
  std::size_t regions = 20;            // regions listed (all are counted)
  std::string units = "mm";            // of the model's coordinates, named in every report
  // A part measured in one direction only is judged on that direction alone (--one-sided);
  // otherwise it is at best inconclusive (VerificationReport::one_sided).
  bool one_sided = false;
};

PartReport make_report(const DistanceSet& distances, const ReportOptions& options);
// What the reports record of this run: ncverify's version, now (util/timestamp.hpp) and the
// command line.
Traceability traceability(const std::string& command_line);

// The report of one direction, or of both (`reverse` not null: the reverse direction of the
// same part, which check_same_part vouches for).
VerificationReport make_verification_report(const DistanceSet& main, const DistanceSet* reverse,
                                            const ReportOptions& options);
// The area-weighted histogram as SVG, with the tolerance limits, the part's name and units.
std::string histogram_svg(const PartReport& report);

// The report's optional files (histogram SVG, regions CSV, histogram CSV, of the main
// direction; empty paths are skipped), opened and written but not committed: the caller
// commits them with its own outputs, so that one path that cannot be written leaves none.
struct ReportFiles {
  std::string histogram_svg;
  std::string regions_csv;
  std::string histogram_csv;
};
std::deque<OutputFile> write_report_files(const PartReport& report, const ReportFiles& files);

// Reads a part's distance files (read_part_distances), makes its report, and writes
// `format(report)` to `output` with the report's optional files; returns the verdict status.
// The steps that end in a report (stats, report) differ only in `format`.
int write_part_report(const std::vector<std::string>& distances, const std::string& samples,
                      const ReportOptions& options, const std::string& command_line,
                      const std::string& output, const ReportFiles& files,
                      const std::function<std::string(const VerificationReport&)>& format);

// `ncverify stats DIST...`.
struct StatsJob {
  // A part's distance files: one per direction, or every shard of a direction's job.
  std::vector<std::string> distances;
  std::string samples;  // the samples file of a single distance file, when not beside it
  std::string output = "-";
  ReportFormat format = ReportFormat::text;
  bool csv_header = true;        // false: --no-header, the row alone
  bool csv_header_only = false;  // --csv-header: the header line alone, no input read
  ReportFiles files;             // empty paths: none
  ReportOptions options;
  std::string command_line;  // for the JSON's traceability
};
// The exit status: 0 within tolerance or without one, 1 out of tolerance.
int run_stats(const StatsJob& job);

}  // namespace ncv
