// The connected out-of-tolerance regions of the workpiece surface, excess and gouge apart.
//
// Two out-of-tolerance samples of the same kind are connected when they are neighbours
// in a lattice (corners of one sub-triangle, which includes a mesh vertex shared by
// several triangles, being one sample) or consecutive points along an edge shared by two
// triangles, whose lattices place distinct samples on it. Each region's area is the
// exact area where the interpolated error lies beyond the limit: a sub-triangle's clipped
// part is convex and touches only corners beyond the limit, all of one region.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "geometry/bounding_box.hpp"
#include "sampling/sampling.hpp"
#include "statistics/sample_extreme.hpp"
#include "statistics/tolerance.hpp"

namespace ncv {

enum class RegionKind { excess, gouge };

struct ErrorRegion {
  RegionKind kind = RegionKind::excess;
  double area = 0;        // where d > upper (excess) or d < lower (gouge)
  SampleExtreme extreme;  // largest d of an excess region, smallest of a gouge
  std::uint64_t samples = 0;
  BoundingBox box;  // of the region's samples
};

// Largest area first; equal areas by their extreme's sample index.
std::vector<ErrorRegion> find_error_regions(const SampleSet& samples, std::span<const double> d,
                                            const Tolerance& tolerance);

// The regions together with which region each sample belongs to, so that a picture can
// name the region under a point (the PLY's region property, the HTML report).
inline constexpr std::uint32_t kNoRegion = 0;
struct RegionMap {
  std::vector<ErrorRegion> regions;          // as find_error_regions
  std::vector<std::uint32_t> sample_region;  // per sample: k + 1 for regions[k], else kNoRegion
};
RegionMap map_error_regions(const SampleSet& samples, std::span<const double> d,
                            const Tolerance& tolerance);

}  // namespace ncv
