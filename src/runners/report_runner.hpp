// The report step (`ncverify stats`, and run's stats phase): the error measures of a distance
// file (docs/METHOD.md "Error measures"), its verdict against a tolerance, the out-of-tolerance
// regions, as text, JSON or CSV, and the histogram as SVG.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "files/distance_file.hpp"
#include "statistics/area_histogram.hpp"
#include "statistics/statistics_report.hpp"
#include "statistics/tolerance.hpp"

namespace ncv {

struct ReportOptions {
  std::optional<Tolerance> tolerance;  // none: no verdict, no regions
  HistogramOptions histogram;          // 64 bins over [d_min, d_max] unless given
  std::size_t regions = 20;            // regions listed (all are counted)
};

PartReport make_report(const DistanceSet& distances, const ReportOptions& options);
// The report of one direction, or of both (`reverse` not null: the reverse direction of the
// same part, which check_same_part vouches for).
VerificationReport make_verification_report(const DistanceSet& main, const DistanceSet* reverse,
                                            const ReportOptions& options);
// The area-weighted histogram as SVG, with the tolerance limits.
std::string histogram_svg(const PartReport& report);

// `ncverify stats DIST...`.
struct StatsJob {
  // A part's distance files: one per direction, or every shard of a direction's job.
  std::vector<std::string> distances;
  std::string samples;  // the samples file of a single distance file, when not beside it
  std::string output = "-";
  ReportFormat format = ReportFormat::text;
  bool csv_header = true;        // false: --no-header, the row alone
  bool csv_header_only = false;  // --csv-header: the header line alone, no input read
  std::string histogram_svg;     // empty: none
  ReportOptions options;
};
// The exit status: 0 within tolerance or without one, 1 out of tolerance.
int run_stats(const StatsJob& job);

}  // namespace ncv
