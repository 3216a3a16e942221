// The sample step (`ncverify sample`, and the first phase of `run` in each direction): a mesh
// sampled on the paper's lattice (docs/METHOD.md "Sampling"), after the memory guard.
#pragma once

#include <optional>
#include <string>

#include "mesh/mesh.hpp"
#include "sampling/sampling.hpp"
#include "sampling/sampling_step.hpp"

namespace ncv {

struct SampleOptions {
  // The default is finer than the paper's recommended 0.6 %: the paper traded accuracy for
  // time, and the grid search makes the finest step of its Table 1 cheap.
  SamplingStep step;  // 0.1 %
  SamplingScheme scheme = SamplingScheme::all;
  bool force = false;  // sample even when the memory guard refuses
  // One share of the samples, for a job spread over a cluster (sampling/shard.hpp).
  std::optional<Shard> shard;
  // How the step is shown in files and reports; empty: as the step reads.
  std::string step_label;
};

struct SampledSurface {
  SampleSet samples;
  SamplingReport report;
  double seconds = 0;
};

// Throws InputError (naming `source`) for a mesh without extent, UsageError when the memory
// guard refuses.
SampledSurface sample_surface(Mesh mesh, const std::string& source, const SampleOptions& options);
// The paper's Table 1 figures of a sampling, on stderr.
void log_sampling(const SampledSurface& sampled);

// The options another samples file was made with: its absolute step (so that the nominal of a
// two-sided check is sampled as densely as its workpiece) and its scheme; the step as given
// reads "0.1% of core_finishing.stl". The rest (--shard, --force) as `given`.
SampleOptions sampling_like(const std::string& samples_path, const SampleOptions& given);

// `ncverify sample MESH -o OUT`.
struct SampleJob {
  std::string mesh;       // path, "-" = standard input
  std::string output;     // path, "-" = standard output
  std::string step_from;  // a samples file whose step and scheme to use; empty: options'
  SampleOptions options;
};
void run_sample(const SampleJob& job);

}  // namespace ncv
