// How a part is handed over, not what it is: its triangles in a random order, as a CAM system
// that writes them from a hash map or by thread does, and the whole part far from the origin,
// as a machine or fixture frame puts it. Both keep the solid, so the errors a verifier finds
// stay the same, while the ways a verifier can go wrong change: a search that relies on
// triangles coming neighbour after neighbour, coordinates with few bits left below the point.
#pragma once

#include <cstdint>

#include "mesh/mesh.hpp"

namespace ncv::gen {

struct Placement {
  bool shuffle = false;
  std::uint64_t seed = 1;  // of the shuffle
  Vec3 offset{0, 0, 0};
};

// The same triangles, each with its corners in the same order, in a permutation fixed by the
// seed (Fisher-Yates on SplitMix64, so every compiler and library gives the same one).
void shuffle_triangles(ncv::Mesh& mesh, std::uint64_t seed);

// Every vertex moved by `offset`, in double precision. A binary STL stores float: far from the
// origin a coordinate keeps fewer bits below the point (at 20,000 mm, steps of 2^-9 mm).
void shift(ncv::Mesh& mesh, const Vec3& offset);

// Shuffles (when asked) and shifts.
void place(ncv::Mesh& mesh, const Placement& placement);

}  // namespace ncv::gen
