// ncverify grid-build MESH -o OUT.grid: the background grid of the mesh distances are
// measured to (paper §3.3).
#include "commands.hpp"
#include "option_groups.hpp"
#include "options.hpp"

namespace ncv::cmd {

void add_grid_build_command(CLI::App& app, CommandContext&) {
  auto job = std::make_shared<GridJob>();
  CLI::App* sub = app.add_subcommand("grid-build", "Build the background grid of a nominal mesh");
  sub->add_option("mesh", job->mesh, "Nominal mesh (STL, PLY, OBJ, OFF; - = stdin)")->required();
  add_output_option(*sub, job->output, "Grid file (default: MESH stem + .grid)");
  add_grid_options(*sub, job->options);
  sub->callback([job] {
    job->output = default_output(job->output, job->mesh, ".grid");
    run_grid_build(*job);
  });
}

}  // namespace ncv::cmd
