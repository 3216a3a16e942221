// The samples file (kind SMPL): the welded workpiece and its lattice samples, everything the
// later steps need. Layout in docs/FORMATS.md. The distance file embeds the same sections.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "files/container.hpp"
#include "sampling/sampling.hpp"

namespace ncv {

// Metadata describing the sample set (workpiece, sampling parameters, counts).
nlohmann::json sample_set_meta(const SampleSet& set);
// Adds the workpiece and sample sections; `set` must outlive the writer.
void add_sample_sections(ContainerWriter& writer, const SampleSet& set);
// Loads and fully validates (indices, lattice bookkeeping, mesh hash) the sample sections.
SampleSet load_sample_set(const Container& container);

// What a samples file was sampled with, from its header alone (the file is still checked
// whole): the absolute step, the step as given, the scheme and the mesh's source.
struct SamplingSettings {
  double step = 0;
  std::string step_spec;
  SamplingScheme scheme = SamplingScheme::all;
  std::string source;
};
SamplingSettings read_sampling_settings(const std::string& path);

void write_samples_file(const SampleSet& set, OutputFile& out);
SampleSet read_samples_file(const std::string& path);

}  // namespace ncv
