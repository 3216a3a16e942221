#include "runners/sample_runner.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <filesystem>
#include <limits>

#include "files/samples_file.hpp"
#include "mesh/mesh_reader.hpp"
#include "util/error.hpp"
#include "util/input_bytes.hpp"
#include "util/memory_guard.hpp"
#include "util/stopwatch.hpp"

namespace ncv {

SampledSurface sample_surface(Mesh mesh, const std::string& source, const SampleOptions& options) {
  Stopwatch clock;
  const double step = options.step.resolve(bounding_box(mesh).diagonal());
  if (!(step > 0)) throw InputError(source, "the mesh has no extent");
  SamplingPlan plan = plan_sampling(mesh, step, options.scheme);
  const std::uint64_t predicted = predicted_sample_count(mesh, plan);
  const std::uint64_t held =
      options.shard ? shard_range(predicted, *options.shard).size() : predicted;
  // predicted_sample_count saturates rather than wrap: say so instead of printing 2^64 - 1.
  const std::string count = held == std::numeric_limits<std::uint64_t>::max()
                                ? "more than 1.8e19"
                                : fmt::format("{}", held);
  check_memory_budget(fmt::format("sampling at step {} ({} samples)", step, count),
                      static_cast<double>(held) * kBytesPerSampleDownstream, options.force);
  SampledSurface sampled;
  sampled.samples = sample_mesh(std::move(mesh), std::move(plan), &sampled.report, options.shard);
  sampled.samples.step_spec = options.step_label.empty() ? options.step.text() : options.step_label;
  sampled.samples.source = source;
  sampled.seconds = clock.seconds();
  return sampled;
}

void log_sampling(const SampledSurface& sampled) {
  const SampleSet& s = sampled.samples;
  const SamplingReport& r = sampled.report;
  spdlog::info("{}: {} triangles, step {} ({}), scheme {}", s.source, r.triangles, s.step,
               s.step_spec, name_of(kSamplingSchemeNames, s.scheme));
  if (s.shard) {
    spdlog::info("shard {}: samples {} to {} of {}", s.shard->text(), s.first_sample,
                 s.first_sample + s.sample_count(), s.total_samples);
  }
  spdlog::info("{} samples; {} triangles too small for the step ({}); {} degenerate; {:.3f} s",
               r.samples, r.small_triangles,
               s.scheme == SamplingScheme::all ? "sampled at their vertices" : "skipped",
               r.degenerate_triangles, sampled.seconds);
}

SampleOptions sampling_like(const std::string& samples_path, const SampleOptions& given) {
  const SamplingSettings settings = read_sampling_settings(samples_path);
  SampleOptions options = given;
  options.step = SamplingStep{settings.step, false};
  options.scheme = settings.scheme;
  options.step_label =
      settings.step_spec + " of " + std::filesystem::path(settings.source).filename().string();
  return options;
}

// The output is opened first, so an unwritable destination fails before any work; the
// report follows the commit, so a failure is the only line on stderr.
void run_sample(const SampleJob& job) {
  const SampleOptions options =
      job.step_from.empty() ? job.options : sampling_like(job.step_from, job.options);
  OutputFile out(job.output, OutputKind::binary);
  const SampledSurface sampled = sample_surface(read_mesh(job.mesh), input_name(job.mesh), options);
  write_samples_file(sampled.samples, out);
  out.commit();
  log_sampling(sampled);
  spdlog::info("wrote {}", out.display_name());
}

}  // namespace ncv
