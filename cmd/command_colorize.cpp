// ncverify colorize DIST -o OUT.ply: the workpiece painted by its error, for MeshLab and
// CloudCompare, with an optional SVG legend.
#include <spdlog/spdlog.h>

#include "colorize_options.hpp"
#include "command_options.hpp"
#include "commands.hpp"
#include "files/distance_file.hpp"
#include "option_checks.hpp"

namespace ncv::cmd {
namespace {

struct ColorizeCommandOptions {
  std::string distances;
  std::string output;
  ColorizeOptions colorize;
};

void run_colorize(const ColorizeCommandOptions& options) {
  const DistanceSet distances = read_distance_file(options.distances);
  write_colorized(distances, default_output(options.output, options.distances, ".ply"),
                  options.colorize);
}

}  // namespace

void add_colorize_command(CLI::App& app, CommandContext&) {
  auto options = std::make_shared<ColorizeCommandOptions>();
  CLI::App* sub = app.add_subcommand("colorize", "Write the workpiece as a coloured PLY");
  sub->add_option("distances", options->distances, "Distance file from `distance` (- = stdin)")
      ->required();
  add_output_option(*sub, options->output, "PLY file (default: DIST stem + .ply)");
  add_colorize_options(*sub, options->colorize);
  sub->add_option("-t,--tol", options->colorize.tolerance,
                  "Tolerance zone LOWER:UPPER or T (selects the tolerance colour map)")
      ->check(valid_zone());
  sub->callback([options] { run_colorize(*options); });
}

}  // namespace ncv::cmd
