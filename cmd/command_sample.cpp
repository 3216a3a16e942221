// ncverify sample MESH -o OUT: lattice sampling (paper §3.1).
#include "commands.hpp"
#include "option_groups.hpp"
#include "options.hpp"

namespace ncv::cmd {

void add_sample_command(CLI::App& app, CommandContext&) {
  auto job = std::make_shared<SampleJob>();
  CLI::App* sub = app.add_subcommand("sample", "Sample a mesh on the paper's lattice");
  sub->add_option("mesh", job->mesh, "Mesh to sample (STL, PLY, OBJ, OFF; - = stdin)")->required();
  add_output_option(*sub, job->output, "Samples file (default: MESH stem + .samples)");
  add_sample_options(*sub, job->options);
  add_parsed_option(*sub, "--shard", job->options.shard, Shard::parse,
                    "Only shard K of N (1/4 .. 4/4) of the samples, for a job spread over a "
                    "cluster: stats and colorize given every shard's distance file report the "
                    "whole job");
  sub->add_option("--step-from", job->step_from,
                  "Use the absolute step and the scheme of this samples file (to sample a "
                  "nominal as densely as its workpiece, for `distance --reverse`)")
      ->excludes("--step")
      ->excludes("--scheme");
  sub->callback([job] {
    job->output = default_output(job->output, job->mesh, ".samples");
    run_sample(*job);
  });
}

}  // namespace ncv::cmd
