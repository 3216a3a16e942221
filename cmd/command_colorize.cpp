// ncverify colorize DIST -o OUT.ply: the sampled surface painted by its error, for MeshLab
// and CloudCompare, with an optional SVG legend.
#include "commands.hpp"
#include "option_groups.hpp"
#include "options.hpp"

namespace ncv::cmd {

void add_colorize_command(CLI::App& app, CommandContext&) {
  auto job = std::make_shared<ColorizeJob>();
  CLI::App* sub = app.add_subcommand("colorize", "Write the workpiece as a coloured PLY");
  sub->add_option("distances", job->distances,
                  "Distance file from `distance` (- = stdin), or every shard's of one direction")
      ->required();
  add_samples_file_option(*sub, job->samples);
  add_output_option(*sub, job->output, "PLY file (default: DIST stem + .ply)");
  add_colorize_options(*sub, job->options);
  add_units_option(*sub, job->options.units);
  sub->add_option("--legend", job->legend_svg, "Also write the colour bar as SVG");
  add_tolerance_option(*sub, job->options.tolerance,
                       "Tolerance zone LOWER:UPPER or T (selects the tolerance colour map)");
  sub->callback([job] {
    job->output = default_output(job->output, job->distances.front(), ".ply");
    run_colorize(*job);
  });
}

}  // namespace ncv::cmd
