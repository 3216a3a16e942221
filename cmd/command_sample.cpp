// ncverify sample WORKPIECE -o OUT: lattice sampling of the workpiece (paper §3.1).
#include <spdlog/spdlog.h>

#include "command_options.hpp"
#include "commands.hpp"
#include "mesh_reader.hpp"
#include "samples_file.hpp"

namespace ncv::cmd {
namespace {

struct SampleOptions {
  std::string workpiece;
  std::string output;
  SamplingOptions sampling;
};

void run_sample(const SampleOptions& options) {
  const SampleSet samples =
      sample_workpiece(read_mesh(options.workpiece), options.workpiece, options.sampling);
  OutputFile out(default_output(options.output, options.workpiece, ".samples"), OutputKind::binary);
  write_samples_file(samples, out);
  out.commit();
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
