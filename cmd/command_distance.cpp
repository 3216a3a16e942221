// ncverify distance SAMPLES GRID -o OUT.dist: the exact signed distance of every sample.
#include "commands.hpp"
#include "option_groups.hpp"
#include "options.hpp"

namespace ncv::cmd {

void add_distance_command(CLI::App& app, CommandContext&) {
  auto job = std::make_shared<DistanceJob>();
  CLI::App* sub =
      app.add_subcommand("distance", "Signed distance from every sample to the nominal");
  sub->add_option("samples", job->samples, "Samples file from `sample` (- = stdin)")->required();
  sub->add_option("grid", job->grid, "Grid file from `grid-build`")->required();
  add_output_option(*sub, job->output, "Distance file (default: SAMPLES stem + .dist)");
  add_distance_options(*sub, job->options);
  sub->add_flag(
      "--reverse", [job](std::int64_t) { job->options.direction = Direction::reverse; },
      "The samples are the nominal's and the grid the workpiece's: sign so that + is "
      "material left (the nominal point inside the workpiece), - a gouge");
  sub->callback([job] {
    job->output = default_output(job->output, job->samples, ".dist");
    run_distance(*job);
  });
}

}  // namespace ncv::cmd
