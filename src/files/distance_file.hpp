// The distance file (kind DIST): the samples (same sections as the samples file, so it is
// self-contained for stats and colorize), the direction, plus, per sample, the signed error,
// the closest point and the closest face of the reference surface. Layout in docs/FORMATS.md.
#pragma once

#include <string>

#include "distance/direction.hpp"
#include "distance/signed_distance.hpp"
#include "files/container.hpp"
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
  SampleSet samples;
  DistanceField field;
  ReferenceInfo reference;
  std::string sign_method;  // the method used (never "automatic")
  std::string search;       // "grid" or "brute-force"
  double triangles_tested_per_sample = 0;
};

void write_distance_file(const DistanceSet& set, OutputFile& out);
// Loads and validates a distance file: the sample sections as the samples file, distances
// finite, closest faces within the nominal.
DistanceSet read_distance_file(const std::string& path);
// The same from a parsed container (read_distance_file's second half; the fuzz target's entry).
DistanceSet load_distance_set(const Container& container);

}  // namespace ncv
