// The samples file (kind SMPL): the sampled mesh, the sampling parameters and each triangle's
// lattice size, from which the samples are made again when the file is read (the points
// themselves are not stored: they are a few times the mesh's size). A shard's file says
// which range of the samples it holds. Layout in docs/FORMATS.md.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "files/container.hpp"
#include "sampling/sampling.hpp"

namespace ncv {

// What a samples file was sampled with, from its header: the absolute step, the step as
// given, the scheme, the mesh's source and the shard, if any.
struct SamplingSettings {
  double step = 0;
  std::string step_spec;
  SamplingScheme scheme = SamplingScheme::all;
  std::string source;
  std::optional<Shard> shard;
};
SamplingSettings read_sampling_settings(const std::string& path);
// The same from a parsed samples or distance file's header.
SamplingSettings sampling_settings(const Container& container);

// The metadata describing the sample set (mesh, parameters, counts, shard).
nlohmann::json sample_set_meta(const SampleSet& set);
// Adds the mesh and lattice sections; `set` must outlive the writer.
void add_sample_sections(ContainerWriter& writer, const SampleSet& set);
// Makes the samples again from the sections: the lattice sizes must be those of the step and
// scheme (the file was not written by another ncverify build that rounds differently), and
// their count within the memory guard. A shard's file makes its range of the samples, or
// all of them with `whole`.
SampleSet load_sample_set(const Container& container, bool whole = false);

// Returns the file's content hash, which a distance file names it by.
std::uint64_t write_samples_file(const SampleSet& set, OutputFile& out);
SampleSet read_samples_file(const std::string& path);

}  // namespace ncv
