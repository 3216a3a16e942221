// The order the distance step searches a block of samples in: by cells of the block's box, in
// Morton order, each cell's samples in their own order. The group search (group_search.hpp)
// measures consecutive queries together, so it pays for how far apart they lie: the samples'
// own order follows the mesh (vertex by vertex in the order the file gives them, then each
// triangle's lattice) and runs in strips, 16 consecutive ones spanning 4.1 mm on the paper-scale
// finishing part (cells of 1.9 mm); in this order they span 1.3 mm, and the search of the
// finishing part takes 60 instead of 69 ns a sample, the roughing part 121 instead of 172 ns
// (docs/PERFORMANCE.md). It depends on the block's points alone.
#pragma once

#include <cstdint>
#include <span>

#include "geometry/vec3.hpp"

namespace ncv {

// The most points spatial_order takes.
inline constexpr std::size_t kMostOrderedPoints = 4096;

// Whether the points in their own order are worth ordering for runs of `run` consecutive
// ones: more than a quarter of those runs span more than `reach` across.
bool runs_lie_apart(std::span<const Vec3> points, std::size_t run, double reach);

// order[k] = the index of the k-th point to search (a permutation of 0 .. points.size() - 1);
// points.size() <= kMostOrderedPoints, order.size() == points.size().
void spatial_order(std::span<const Vec3> points, std::span<std::uint16_t> order);

}  // namespace ncv
