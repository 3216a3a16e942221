// The order the distance step measures a sample set in, where the set's own order scatters.
//
// The samples are numbered vertex by vertex, then each triangle's own lattice points
// triangle by triangle (sampling.hpp). The vertices are numbered in a spatial order when a
// file's order scatters them (mesh/vertex_order.hpp), but the triangles keep the file's order,
// which every area sum follows. Where a file lists its facets in random order, consecutive
// triangles lie anywhere on the part, and so do their own samples: the search then finds few
// runs of nearby samples to measure together (search/group_search.hpp) and no useful hint from
// one sample to the next. The distance step can measure the samples in any order (each value
// is computed on its own and written to its own slot), so such a set is measured in this
// order instead: the vertex samples as they are, then the triangles' own samples, the
// triangles taken in Morton order of their first corner's cell (geometry/morton_cells.hpp).
// Costs about 1-3 ms on a paper-scale part (20 k triangles with own samples among 1.24 M).
// Nothing the step writes depends on the order but its search counters.
#pragma once

#include <cstdint>

#include "sampling/sampling.hpp"
#include "util/buffer.hpp"

namespace ncv {

// True when the set holds all its samples (no shard), at least kLeastScatteredSamples of them
// triangles' own, and the first corners of consecutive triangles with own samples lie more
// than a sixteenth of the mesh's bounding-box diagonal apart, at the median over up to 4096
// pairs spread evenly through the triangles. Files written neighbour after neighbour measure
// below 0.01, ones with their facets shuffled about a third.
inline constexpr std::uint64_t kLeastScatteredSamples = std::uint64_t{1} << 16;
bool own_samples_scattered(const SampleSet& samples);

// The triangles' own samples (every sample number from the first one that is not a vertex's,
// once), triangle by triangle, the triangles by their first corner's Morton cell (within a
// cell in their order), each triangle's samples in their order; the vertex samples before
// them keep theirs. The same whatever the thread count. Empty when the set's own order serves
// (not own_samples_scattered) or its numbers do not fit 32 bits.
Buffer<std::uint32_t> measuring_order(const SampleSet& samples);

}  // namespace ncv
