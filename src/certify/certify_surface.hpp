// Certification of one direction (docs/CERTIFICATION.md): bounds on the signed error over
// the whole sampled surface, between its samples, refined until the interval for the largest
// and for the smallest error is narrower than asked.
//
// Every lattice sub-triangle ("patch") of the sampled triangles gets bounds from its corners
// (patch_bounds.hpp). A patch whose bound lies farther than the width asked beyond the
// measured extreme is "open": it is bounded again by the reference triangles near it, and if
// still open, split into four at its edge midpoints, which are measured exactly as samples are
// (only the new midpoints). Splitting goes round by round over all open patches, so that the
// points it adds and the result do not depend on the thread count, until none is open, the
// cap on added points would be passed, or the patches are as small as rounding allows.
//
// Shards: a sampled triangle belongs to the shard that holds its anchor sample (its first
// own lattice point, or its first corner when it has none); corners held by another shard
// are measured again, to the same value.
#pragma once

#include <cstdint>
#include <optional>

#include "certify/certificate.hpp"
#include "distance/side_rule.hpp"
#include "distance/signed_distance.hpp"
#include "sampling/sampling.hpp"
#include "search/search_index.hpp"

namespace ncv {

// The interval width refinement aims at when none is asked: 0.001 model units (1 um on a
// part in mm). It does not depend on the tolerance zone, which the distance step (where
// certification runs) does not know: `run` and its steps give the same certificate.
inline constexpr double kDefaultCertifyWidth = 0.001;
// The default cap on added points for a small lattice.
inline constexpr std::uint64_t kLeastPointsCap = 20000;

struct CertifyOptions {
  std::optional<double> width;  // in model units (> 0); none: the default above
  // The most points refinement may add; 0: as many as the lattice has samples (at least
  // kLeastPointsCap), so certification at most doubles the measuring.
  std::uint64_t points_cap = 0;
};

// Memory an added point costs while refinement works (the patches it splits and makes).
inline constexpr double kBytesPerCertifyPoint = 170;

// The cap on added points the options give for a lattice of this many samples.
std::uint64_t certify_points_cap(const CertifyOptions& options, std::uint64_t total_samples);

// `raw` holds the held samples' signed distances to the reference (+ outside it, before a
// reverse direction's negation) and closest faces; `side` is the rule that signed them.
Certificate certify_surface(const SampleSet& samples, const DistanceField& raw,
                            const SearchIndex& index, const SideRule& side,
                            const CertifyOptions& options);

}  // namespace ncv
