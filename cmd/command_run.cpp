// ncverify run WORKPIECE NOMINAL: sample, grid-build, distance, stats and colorize in one
// go, keeping every intermediate file in an output folder.
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <filesystem>
#include <optional>

#include "colorize_options.hpp"
#include "command_options.hpp"
#include "commands.hpp"
#include "files/grid_file.hpp"
#include "files/samples_file.hpp"
#include "mesh/mesh_reader.hpp"
#include "option_checks.hpp"
#include "report_options.hpp"
#include "search/search_index.hpp"
#include "util/input_bytes.hpp"
#include "util/memory_guard.hpp"
#include "util/stopwatch.hpp"

namespace ncv::cmd {
namespace {

namespace fs = std::filesystem;

struct RunOptions {
  std::string workpiece;
  std::string nominal;
  std::string folder;
  SamplingOptions sampling;
  double cell_size = 0;
  DistanceStepOptions distance;
  ReportOptions report;
  ColorizeOptions colorize;
  std::string format = "text";
  std::string timings;
};

// Wall time per phase; writing the intermediate files is its own phase ("write"), so the
// compute phases are what the algorithm costs.
class PhaseLog {
 public:
  // Ends the phase running since the last call.
  void done(const std::string& phase) {
    add(phase, clock_.seconds());
    clock_.restart();
  }
  template <class Work>
  void time(const std::string& phase, Work&& work) {
    work();
    done(phase);
  }
  void summary(const std::string& timings_path, const DistanceSet& distances) const {
    std::string line;
    double total = 0;
    nlohmann::json phases = nlohmann::json::object();
    for (const auto& [phase, seconds] : phases_) {
      line += fmt::format("{} {:.3f} s, ", phase, seconds);
      phases[phase] = seconds;
      total += seconds;
    }
    spdlog::info("phases: {}total {:.3f} s", line, total);
    if (timings_path.empty()) return;
    const nlohmann::json timings = {
        {"phases", phases},
        {"total", total},
        {"triangles", distances.samples.workpiece.triangle_count()},
        {"samples", distances.samples.sample_count()},
        {"nominal_triangles", distances.nominal.triangles},
        {"triangles_tested_per_sample", distances.triangles_tested_per_sample},
        {"peak_memory_bytes", peak_memory_bytes()}};
    OutputFile out(timings_path, OutputKind::text);
    out.write(timings.dump(2) + "\n");
    out.commit();
  }

 private:
  void add(const std::string& phase, double seconds) {
    for (auto& [name, total] : phases_) {
      if (name == phase) {
        total += seconds;
        return;
      }
    }
    phases_.push_back({phase, seconds});
  }

  Stopwatch clock_;
  std::vector<std::pair<std::string, double>> phases_;
};

std::string stem(const std::string& path) {
  return path == "-" ? "stdin" : fs::path(path).stem().string();
}

template <class Write>
void write_file(const fs::path& path, OutputKind kind, Write&& write) {
  OutputFile out(path.string(), kind);
  write(out);
  out.commit();
}

void run_all(const RunOptions& options, CommandContext& context) {
  const std::string part = stem(options.workpiece);
  const fs::path folder =
      options.folder.empty() ? fs::path(part + ".ncverify") : fs::path(options.folder);
  std::error_code error;
  fs::create_directories(folder, error);
  if (error)
    throw InputError(folder.string(), "cannot create the output folder: " + error.message());
  PhaseLog phases;

  Mesh workpiece = read_mesh(options.workpiece);
  Mesh nominal = read_mesh(options.nominal);
  refuse_if_apart(bounding_box(workpiece), input_name(options.workpiece), bounding_box(nominal),
                  input_name(options.nominal));
  phases.done("read");

  SampledWorkpiece sampled =
      sample_workpiece(std::move(workpiece), options.workpiece, options.sampling);
  log_sampling(sampled);
  SampleSet& samples = sampled.samples;
  phases.done("sample");
  phases.time("write", [&] {
    write_file(folder / (part + ".samples"), OutputKind::binary,
               [&](OutputFile& out) { write_samples_file(samples, out); });
  });

  GridStatistics grid_statistics;
  const PreparedNominal grid = build_nominal_grid(std::move(nominal), input_name(options.nominal),
                                                  GridOptions{options.cell_size}, &grid_statistics);
  std::optional<SearchIndex> search(std::in_place, grid.nominal->corners(), grid.grid);
  phases.done("grid-build");
  phases.time("write", [&] {
    write_file(folder / (stem(options.nominal) + ".grid"), OutputKind::binary,
               [&](OutputFile& out) { write_grid_file(grid, grid_statistics, out); });
  });

  double distance_seconds = 0;
  const DistanceSet distances =
      measure_distances(std::move(samples), grid, *search, options.distance, &distance_seconds);
  search.reset();  // its boxes (69 MB for a 1.6 M-triangle nominal) are not needed past here
  log_distance_report(distances, distance_seconds);
  phases.done("distance");
  phases.time("write", [&] {
    write_file(folder / (part + ".dist"), OutputKind::binary,
               [&](OutputFile& out) { write_distance_file(distances, out); });
  });

  ReportOptions report_options = options.report;
  if (report_options.histogram_svg.empty()) {
    report_options.histogram_svg = (folder / (part + ".histogram.svg")).string();
  }
  const PartReport report = make_report(distances, report_options);
  write_file(folder / (part + ".report.txt"), OutputKind::text,
             [&](OutputFile& out) { out.write(format_report(report, ReportFormat::text)); });
  write_file(folder / (part + ".report.json"), OutputKind::text,
             [&](OutputFile& out) { out.write(format_report(report, ReportFormat::json)); });
  write_histogram_if_asked(report, report_options);
  phases.done("stats");

  ColorizeOptions colorize = options.colorize;
  colorize.tolerance = options.report.tolerance;
  if (colorize.legend_svg.empty()) colorize.legend_svg = (folder / (part + ".legend.svg")).string();
  write_colorized(distances, (folder / (part + ".ply")).string(), colorize);
  phases.done("colorize");

  OutputFile out("-", OutputKind::text);
  out.write(format_report(report, parse_report_format(options.format)));
  out.commit();
  phases.summary(options.timings, distances);
  spdlog::info("outputs in {}/", folder.string());
  context.exit_status = verdict_status(report);
}

}  // namespace

void add_run_command(CLI::App& app, CommandContext& context) {
  auto options = std::make_shared<RunOptions>();
  CLI::App* sub = app.add_subcommand(
      "run", "Verify WORKPIECE against NOMINAL in one go (all steps, intermediates kept)");
  sub->add_option("workpiece", options->workpiece, "Machined workpiece mesh")->required();
  sub->add_option("nominal", options->nominal, "Nominal part mesh")->required();
  sub->add_option("-d,--dir", options->folder,
                  "Output folder (default: WORKPIECE stem + .ncverify)");
  add_sampling_options(*sub, options->sampling);
  sub->add_option("--cell", options->cell_size, "Grid cell edge in model units")
      ->check(valid_positive_length());
  add_distance_options(*sub, options->distance);
  add_report_options(*sub, options->report);
  add_colorize_options(*sub, options->colorize);
  sub->add_option("--format", options->format, "Report on stdout: text, json or csv")
      ->check(CLI::IsMember({"text", "json", "csv"}))
      ->capture_default_str();
  sub->add_option("--timings", options->timings,
                  "Also write each phase's wall time and the peak memory as JSON (benchmarks)");
  sub->callback([options, &context] { run_all(*options, context); });
}

}  // namespace ncv::cmd
