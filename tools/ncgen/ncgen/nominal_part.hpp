// The nominal part as a CAD system would export it: the mould core tessellated to a chord
// tolerance, planar faces in few large triangles and curved faces in many small ones.
#pragma once

#include <vector>

#include "mesh/mesh.hpp"
#include "ncgen/grid.hpp"
#include "ncgen/mould_core.hpp"

namespace ncv::gen {

// Square RTIN tiles: 40 mm divides both sides of the 120 x 80 block.
constexpr double tile_size = 40.0;

struct NominalOptions {
  int level = 9;                  // 2^level cells per tile: 0.078 mm samples
  double chord_tolerance = 0.08;  // mm, as the paper's nominal STL
};

Grid part_grid(const MouldCore& part, int level);
std::vector<float> sample_heights(const Grid& grid, const MouldCore& part);
ncv::Mesh nominal_mesh(const MouldCore& part, const NominalOptions& options);

}  // namespace ncv::gen
