// ncverify sample WORKPIECE -o OUT: lattice sampling of the workpiece (paper §3.1).
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <filesystem>

#include "command_options.hpp"
#include "commands.hpp"
#include "input_bytes.hpp"
#include "memory_guard.hpp"
#include "mesh_reader.hpp"
#include "samples_file.hpp"
#include "sampling_step.hpp"

namespace ncv::cmd {
namespace {

struct SampleOptions {
  std::string workpiece;
  std::string output;
  std::string step = kDefaultStep;
  std::string scheme = "all";
  bool force = false;
};

void run_sample(const SampleOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  MeshReadReport read_report;
  Mesh mesh = read_mesh(options.workpiece, &read_report);
  const SamplingScheme scheme = parse_scheme_option(options.scheme);
  SamplingStep step_spec = SamplingStep::parse(options.step);
  const double step = step_spec.resolve(bounding_box(mesh).diagonal());
  if (!(step > 0)) throw InputError(input_name(options.workpiece), "the mesh has no extent");

  const std::uint64_t predicted = predicted_sample_count(mesh, step, scheme);
  check_memory_budget(fmt::format("sampling at step {} ({} samples)", step, predicted),
                      static_cast<double>(predicted) * kBytesPerSampleDownstream, options.force);

  SamplingReport report;
  SampleSet set = sample_mesh(std::move(mesh), step, scheme, &report);
  set.step_spec = options.step;
  set.workpiece_source = input_name(options.workpiece);
  OutputFile out(default_output(options.output, options.workpiece, ".samples"), OutputKind::binary);
  write_samples_file(set, out);
  out.commit();

  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  spdlog::info("{}: {} triangles ({}), step {} ({}), scheme {}", input_name(options.workpiece),
               report.triangles, format_name(read_report.format), step, options.step,
               options.scheme);
  spdlog::info("{} samples; {} triangles too small for the step ({}); {} degenerate; {:.3f} s",
               report.samples, report.small_triangles,
               scheme == SamplingScheme::all ? "sampled at their vertices" : "skipped",
               report.degenerate_triangles, seconds);
  spdlog::info("wrote {}", out.display_name());
}

}  // namespace

void add_sample_command(CLI::App& app, CommandContext&) {
  auto options = std::make_shared<SampleOptions>();
  CLI::App* sub = app.add_subcommand("sample", "Sample a workpiece mesh on the paper's lattice");
  sub->add_option("workpiece", options->workpiece, "Workpiece mesh (STL, PLY, OBJ, OFF; - = stdin)")
      ->required();
  add_output_option(*sub, options->output, "Samples file (default: WORKPIECE stem + .samples)");
  add_step_options(*sub, options->step, options->scheme);
  sub->add_flag("--force", options->force, "Sample even when the sample count looks unreasonable");
  sub->callback([options] { run_sample(*options); });
}

}  // namespace ncv::cmd
