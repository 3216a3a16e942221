// The stats report: ErrorStatistics and the out-of-tolerance regions of one part, in one or
// both directions (distance/direction.hpp), as a readable text table, as JSON (stable keys,
// documented in docs/REPORTS.md) or as CSV (one header line and one row, so the rows of many
// parts concatenate into one table). JSON and CSV numbers are written in their shortest
// round-tripping form; the text report rounds them to what the measurement supports
// (statistics/readable_numbers.hpp) and names the units.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "files/distance_file.hpp"
#include "geometry/bounding_box.hpp"
#include "statistics/error_regions.hpp"
#include "statistics/error_statistics.hpp"
#include "statistics/readable_numbers.hpp"
#include "statistics/verdict.hpp"
#include "util/enum_names.hpp"

namespace ncv {

// The report of one direction.
struct PartReport {
  std::string part;  // the workpiece's file stem
  const DistanceSet* distances = nullptr;
  ErrorStatistics statistics;
  std::vector<ErrorRegion> regions;          // empty without a tolerance
  std::vector<std::uint32_t> sample_region;  // per sample (RegionMap); empty without one
  std::size_t listed_regions = 20;           // regions written out (all are counted)
  std::string units = "mm";                  // of lengths; areas are in units²
  BoundingBox surface_box;  // of the sampled surface, whose size sets the numbers' rounding

  // The verdict against the tolerance (statistics/verdict.hpp); none without a tolerance.
  std::optional<Verdict> verdict() const;
  bool fails() const { return verdict() == Verdict::fail; }
};

PartReport make_part_report(const DistanceSet& distances, const std::optional<Tolerance>& tolerance,
                            const HistogramOptions& histogram);

// The numbers of the text report: rounded to the sampled surface's resolution, in its units.
NumberStyle report_number_style(const PartReport& report);

// Where a report came from, so that a result found later can be traced to its inputs.
struct Traceability {
  std::string version = NCV_VERSION;  // of ncverify
  std::string date;                   // ISO 8601, UTC
  std::string command_line;           // as typed, arguments quoted where needed
};

// A part's report: `main` is the forward direction, or the only direction measured; `reverse`
// is there when both were. The part fails when either direction does, and passes only when
// both pass, or when the one direction measured passes and was asked for alone (`one_sided`):
// each direction misses what only the other sees (docs/METHOD.md "Both directions").
struct VerificationReport {
  PartReport main;
  std::optional<PartReport> reverse;
  bool one_sided = false;  // one direction judged on its own (--one-sided)
  Traceability trace{};

  // The worse of the directions' verdicts, a pass of one direction alone inconclusive unless
  // one_sided; none without a tolerance.
  std::optional<Verdict> verdict() const;
  // Why the verdict is inconclusive when only one direction was measured and it passes: the
  // direction missing, what it would have seen and how to give it; empty otherwise.
  std::string missing_direction_reason() const;
  bool fails() const { return verdict() == Verdict::fail; }
  // The two-sided Hausdorff distance: the larger max |d| of the two directions.
  std::optional<double> hausdorff() const;
};

nlohmann::json report_json(const VerificationReport& report);
std::string report_text(const VerificationReport& report);
std::string report_csv_header();
std::string report_csv_row(const VerificationReport& report);
// Every out-of-tolerance region of one direction, one row each, largest first (not only the
// listed ones).
std::string regions_csv(const PartReport& report);
// The area-weighted histogram of one direction, one row per bin, with the area outside it.
std::string histogram_csv(const PartReport& report);

enum class ReportFormat { text, json, csv };
inline constexpr EnumName<ReportFormat> kReportFormatNames[] = {
    {ReportFormat::text, "text"}, {ReportFormat::json, "json"}, {ReportFormat::csv, "csv"}};
// The whole report in one format; csv_header adds the CSV header line.
std::string format_report(const VerificationReport& report, ReportFormat format,
                          bool csv_header = true);

// The exit status the verdict implies: 0 pass or no tolerance, 1 out of tolerance (fail),
// 3 inconclusive.
int verdict_status(const VerificationReport& report);

}  // namespace ncv
