// A binary STL's facets welded into a Mesh in parallel, to the mesh one VertexWelder over
// every corner in file order gives, bit for bit: a vertex per distinct corner (-0 and +0
// equal), numbered in the order of its first corner and carrying that corner's coordinates.
//
// The corners are split by a hash of their coordinates into partitions, each welded on its
// own in file order (a small table per partition, in cache), so equal corners meet in one
// partition and each finds its first occurrence; the first occurrences are then numbered in
// file order. One serial weld of the 3.75 M corners of the 1.25 M-facet finishing part took
// 0.13-0.15 s of its read, and 0.25 s for the same part with its facets in random order
// (docs/PERFORMANCE.md).
#pragma once

#include <cstdint>
#include <optional>

#include "mesh/mesh.hpp"

namespace ncv {

struct WeldedFacets {
  Mesh mesh;
  std::optional<std::uint64_t> non_finite;  // the first facet with a NaN or infinite corner
};

// `facets`: `count` facets of 50 bytes (a normal, three corners of three little-endian
// floats, an attribute). With a non-finite coordinate, the mesh is left empty.
WeldedFacets weld_binary_facets(const char* facets, std::uint64_t count);

}  // namespace ncv
