// The options several subcommands share, each declared once into its runner's typed struct.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>

#include "runners/colorize_runner.hpp"
#include "runners/distance_runner.hpp"
#include "runners/grid_runner.hpp"
#include "runners/report_runner.hpp"
#include "runners/sample_runner.hpp"

namespace ncv::cmd {

void add_sample_options(CLI::App& sub, SampleOptions& options);
void add_grid_options(CLI::App& sub, GridOptions& options);
void add_distance_options(CLI::App& sub, DistanceOptions& options);
void add_tolerance_option(CLI::App& sub, std::optional<Tolerance>& tolerance,
                          const std::string& description);
// --bins, --histogram-range, --regions, --units (the tolerance is declared apart).
void add_report_options(CLI::App& sub, ReportOptions& options);
// stats' and report's --one-sided (run's is its own: it also measures one direction only).
void add_one_sided_option(CLI::App& sub, ReportOptions& options);
// --regions-csv, --histogram-csv.
void add_report_file_options(CLI::App& sub, ReportFiles& files);
void add_units_option(CLI::App& sub, std::string& units);
// --samples: the samples file a distance file names, when it is not where the file says.
void add_samples_file_option(CLI::App& sub, std::string& samples);
// --map, --range (the tolerance is declared apart).
void add_color_map_options(CLI::App& sub, ColorizeOptions& options);
// The colour map options and --coarse.
void add_colorize_options(CLI::App& sub, ColorizeOptions& options);

}  // namespace ncv::cmd
