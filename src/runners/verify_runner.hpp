// `ncverify run WORKPIECE NOMINAL`: every step in one go (sample, grid, distance, report,
// colorize) in both directions (docs/METHOD.md "Both directions"), keeping each step's output
// in a folder, the report on standard output.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "runners/colorize_runner.hpp"
#include "runners/distance_runner.hpp"
#include "runners/grid_runner.hpp"
#include "runners/html_runner.hpp"
#include "runners/report_runner.hpp"
#include "runners/sample_runner.hpp"

namespace ncv {

struct VerifyOptions {
  SampleOptions sampling;
  GridOptions grid;
  DistanceOptions distance;
  ReportOptions report;      // its tolerance also selects the colour map
  ColorizeOptions colorize;  // its tolerance is the report's
  // Also the reverse direction: the nominal sampled with the workpiece's absolute step and
  // measured against the workpiece, so a feature the workpiece lacks cannot pass.
  bool two_sided = true;
};

// How run paints each direction: the colour options with the report's tolerance zone.
ColorizeOptions colorize_options(const VerifyOptions& options);
// How run reports: the report options, a direction left out on purpose (one-sided) judged on
// its own.
ReportOptions report_options(const VerifyOptions& options);

// What a verification hands on as each step finishes, in order: run logs each step, times it
// and writes its file; the library (mesh_verification.hpp) keeps only the results.
struct StepHooks {
  std::function<void(const SampledSurface&, Direction)> sampled;
  std::function<void(const IndexedSurface&, Direction)> indexed;
  std::function<void(const DistanceSet&, double seconds)> measured;  // knows its direction
};

struct Measurements {
  DistanceSet forward;                 // the workpiece's samples against the nominal
  std::optional<DistanceSet> reverse;  // the nominal's against the workpiece (two-sided)
};

// The measuring steps of a verification, in memory: the workpiece sampled and measured
// against the nominal's grid, then (two-sided) the nominal sampled at the workpiece's
// absolute step and scheme and measured against the workpiece's grid.
Measurements measure_part(Mesh workpiece, const std::string& workpiece_source, Mesh nominal,
                          const std::string& nominal_source, const VerifyOptions& options,
                          const StepHooks& hooks = {});

// What `run` leaves in its folder: everything (the intermediate files too, so each step can
// be inspected or rerun), the reports and pictures only, or nothing (the report on standard
// output and the exit status are the result).
enum class Keep { all, reports, none };
inline constexpr EnumName<Keep> kKeepNames[] = {
    {Keep::all, "all"}, {Keep::reports, "reports"}, {Keep::none, "none"}};

struct RunJob {
  std::string workpiece;
  std::string nominal;
  std::string folder;  // empty: WORKPIECE stem + ".ncverify"
  VerifyOptions options;
  ReportFormat format = ReportFormat::text;  // of the report on standard output
  Keep keep = Keep::all;
  std::string timings;        // where to write the phase times; empty: nowhere
  std::string histogram_svg;  // empty: PART.histogram.svg in the folder
  std::string legend_svg;     // empty: PART.legend.svg in the folder
  std::string command_line;   // for the reports' traceability
};

// The exit status: 0 within tolerance (both directions) or without one, 1 out of tolerance.
int run_verification(const RunJob& job);

}  // namespace ncv
