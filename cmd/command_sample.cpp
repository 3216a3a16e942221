// ncverify sample WORKPIECE -o OUT: lattice sampling of the workpiece (paper §3.1).
#include <spdlog/spdlog.h>

#include "command_options.hpp"
#include "commands.hpp"
#include "files/samples_file.hpp"
#include "mesh/mesh_reader.hpp"

namespace ncv::cmd {
namespace {

struct SampleOptions {
  std::string workpiece;
  std::string output;
  SamplingOptions sampling;
};

// The output is opened first, so an unwritable destination fails before any work; the
// report follows the commit, so a failure is the only line on stderr.
void run_sample(const SampleOptions& options) {
  OutputFile out(default_output(options.output, options.workpiece, ".samples"), OutputKind::binary);
  const SampledWorkpiece sampled =
      sample_workpiece(read_mesh(options.workpiece), options.workpiece, options.sampling);
  write_samples_file(sampled.samples, out);
  out.commit();
  log_sampling(sampled);
  spdlog::info("wrote {}", out.display_name());
}

}  // namespace

void add_sample_command(CLI::App& app, CommandContext&) {
  auto options = std::make_shared<SampleOptions>();
  CLI::App* sub = app.add_subcommand("sample", "Sample a workpiece mesh on the paper's lattice");
  sub->add_option("workpiece", options->workpiece, "Workpiece mesh (STL, PLY, OBJ, OFF; - = stdin)")
      ->required();
  add_output_option(*sub, options->output, "Samples file (default: WORKPIECE stem + .samples)");
  add_sampling_options(*sub, options->sampling);
  sub->callback([options] { run_sample(*options); });
}

}  // namespace ncv::cmd
