#include "command_options.hpp"

#include <filesystem>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "files/samples_file.hpp"
#include "option_checks.hpp"
#include "sampling/sampling_step.hpp"
#include "util/error.hpp"
#include "util/input_bytes.hpp"
#include "util/memory_guard.hpp"
#include "util/stopwatch.hpp"

namespace ncv::cmd {

SamplingScheme parse_scheme_option(const std::string& name) {
  if (name == "all") return SamplingScheme::all;
  if (name == "paper-ii") return SamplingScheme::paper_ii;
  throw UsageError("unknown scheme '" + name + "': use all or paper-ii");
}

SampledWorkpiece sample_workpiece(Mesh mesh, const std::string& path,
                                  const SamplingOptions& options) {
  Stopwatch clock;
  const SamplingScheme scheme = parse_scheme_option(options.scheme);
  const double step = SamplingStep::parse(options.step).resolve(bounding_box(mesh).diagonal());
  if (!(step > 0)) throw InputError(input_name(path), "the mesh has no extent");
  SamplingPlan plan = plan_sampling(mesh, step, scheme);
  const std::uint64_t predicted = predicted_sample_count(mesh, plan);
  check_memory_budget(fmt::format("sampling at step {} ({} samples)", step, predicted),
                      static_cast<double>(predicted) * kBytesPerSampleDownstream, options.force);
  SampledWorkpiece sampled;
  sampled.samples = sample_mesh(std::move(mesh), std::move(plan), &sampled.report);
  sampled.samples.step_spec = options.step;
  sampled.samples.workpiece_source = input_name(path);
  sampled.seconds = clock.seconds();
  return sampled;
}

void log_sampling(const SampledWorkpiece& sampled) {
  const SampleSet& s = sampled.samples;
  const SamplingReport& r = sampled.report;
  spdlog::info("{}: {} triangles, step {} ({}), scheme {}", s.workpiece_source, r.triangles, s.step,
               s.step_spec, scheme_name(s.scheme));
  spdlog::info("{} samples; {} triangles too small for the step ({}); {} degenerate; {:.3f} s",
               r.samples, r.small_triangles,
               s.scheme == SamplingScheme::all ? "sampled at their vertices" : "skipped",
               r.degenerate_triangles, sampled.seconds);
}

std::string default_output(const std::string& output, const std::string& input,
                           const std::string& extension) {
  if (!output.empty()) return output;
  if (input == "-") return "-";
  return std::filesystem::path(input).stem().string() + extension;
}

void add_output_option(CLI::App& sub, std::string& output, const std::string& description) {
  sub.add_option("-o,--output", output, description + "; - = standard output");
}

void add_sampling_options(CLI::App& sub, SamplingOptions& options) {
  sub.add_option("-s,--step", options.step,
                 "Sampling step: model units (0.05) or % of the bounding-box diagonal (0.1%)")
      ->check(valid_step())
      ->capture_default_str();
  sub.add_option("--scheme", options.scheme,
                 "all: tiny triangles give their vertices (paper scheme I); paper-ii: they are "
                 "skipped (the paper's baseline)")
      ->check(CLI::IsMember({"all", "paper-ii"}))
      ->capture_default_str();
  sub.add_flag("--force", options.force, "Sample even when the sample count looks unreasonable");
}

void add_distance_options(CLI::App& sub, DistanceStepOptions& options) {
  const std::map<std::string, SignMethod> methods = {{"auto", SignMethod::automatic},
                                                     {"pseudonormal", SignMethod::pseudonormal},
                                                     {"winding", SignMethod::winding},
                                                     {"paper", SignMethod::paper}};
  sub.add_option("--sign", options.sign,
                 "auto: pseudonormal for a closed oriented nominal, else winding number; "
                 "paper: the sample's own normal (the paper's rule)")
      ->transform(CLI::CheckedTransformer(methods))
      ->default_str("auto");
  sub.add_flag("--brute-force", options.brute_force,
               "Test every nominal triangle for every sample (the reference; slow)");
}

}  // namespace ncv::cmd
