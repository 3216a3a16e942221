// The distance file (kind DIST): per sample, the signed error and the closest face of the
// reference surface, the direction, and how it was measured. It names its samples file by
// its path (relative to the distance file) and its content hash rather than repeating it; a
// distance file made from a stream of samples holds them itself (the mesh and the lattice
// sizes). Closest points are not stored: the exact kernel gives them again from the sample
// and the face. Layout in docs/FORMATS.md.
#pragma once

#include <optional>
#include <string>

#include "certify/certificate.hpp"
#include "distance/direction.hpp"
#include "distance/signed_distance.hpp"
#include "files/container.hpp"
#include "files/samples_file.hpp"
#include "sampling/sampling.hpp"

namespace ncv {

// What the distance file records of the surface it was measured against.
struct ReferenceInfo {
  std::string source;
  std::uint64_t hash = 0;
  std::uint64_t triangles = 0;
  BoundingBox box;
};

// The samples of one surface and their signed errors against the other. Forward: the
// workpiece's samples against the nominal (the reference). Reverse: the nominal's samples
// against the workpiece, field.distance negated so that + is material left in both.
struct DistanceSet {
  Direction direction = Direction::forward;
  SampleSet samples;    // all of the lattice's samples, or a shard's range
  DistanceField field;  // per sample held
  ReferenceInfo reference;
  std::string sign_method;             // the method used (never "auto")
  std::string search;                  // "grid" or "brute-force"
  std::uint64_t triangles_tested = 0;  // exact point-triangle tests over the samples held
  // Bounds on the error between the samples (docs/CERTIFICATION.md); none when the file was
  // made without certification.
  std::optional<Certificate> certificate;

  double triangles_tested_per_sample() const {
    return samples.sample_count()
               ? static_cast<double>(triangles_tested) / static_cast<double>(samples.sample_count())
               : 0.0;
  }
};

// Where a distance file finds its samples: the samples file at `path` (relative to the
// distance file's folder; for a distance file on standard output, to the current one) whose
// content hash is `hash`. Without a link, the samples are written into the distance file.
struct SamplesLink {
  std::string path;
  std::uint64_t hash = 0;
};

// The link from a distance file at `distance_path` to the samples file at `samples_path`
// whose content hash is `hash`; none (the samples go into the distance file) when the samples
// came from standard input.
std::optional<SamplesLink> link_samples(const std::string& samples_path, std::uint64_t hash,
                                        const std::string& distance_path);

void write_distance_file(const DistanceSet& set, const std::optional<SamplesLink>& samples,
                         OutputFile& out);

// A distance file as read, its samples not made yet: what merging shards needs.
struct DistanceRecords {
  DistanceRecords(Container parsed, std::string given_path)
      : container(std::move(parsed)), path(std::move(given_path)) {}

  Container container;
  std::string path;  // as given, for finding a linked samples file and for messages
  Direction direction = Direction::forward;
  std::optional<Shard> shard;
  std::uint64_t first_sample = 0;
  std::uint64_t total_samples = 0;
  std::uint64_t mesh_hash = 0;  // of the sampled mesh
  SamplingSettings sampling;
  ReferenceInfo reference;
  std::string sign_method;
  std::string search;
  std::uint64_t triangles_tested = 0;
  std::optional<Certificate> certificate;
  Buffer<double> distance;
  Buffer<std::uint32_t> closest_face;
};

DistanceRecords read_distance_records(const std::string& path);
// The same from a parsed container (the fuzz target's entry); `path` locates a linked
// samples file.
DistanceRecords load_distance_records(Container container, const std::string& path);
// The samples the records were measured at: from the distance file itself, from
// `samples_path` when given, or from the linked samples file (beside the distance file, or
// where its path leads from the current folder); a samples file whose content is not the one
// the distance file names is refused. `whole` makes every sample of the lattice, not only a
// shard's range.
SampleSet load_linked_samples(const DistanceRecords& records, const std::string& samples_path,
                              bool whole);
// Records and their samples together; the records' arrays move into the set.
DistanceSet assemble_distance_set(DistanceRecords records, SampleSet samples);
// read_distance_records, then load_linked_samples and assemble_distance_set.
DistanceSet read_distance_file(const std::string& path, const std::string& samples_path = {});

}  // namespace ncv
