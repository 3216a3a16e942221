// Machined workpieces of the mould core: the Z-map after each milling stage, closed into a
// solid whose triangles are as non-uniform as an NC simulation's (large where flat, tiny at
// cusps and steps).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "mesh/mesh.hpp"
#include "ncgen/milling_simulation.hpp"
#include "ncgen/mould_core.hpp"

namespace ncv::gen {

// Height of the stock block the workpieces are milled from.
constexpr double stock_height = 32.0;

// Below some size the triangle budget would need chord errors like the roughing steps
// themselves; past this tolerance the workpiece keeps more triangles than asked instead.
constexpr float coarsest_workpiece_tolerance = 0.5f;

struct Workpiece {
  ncv::Mesh mesh;
  float tolerance = 0;  // chord tolerance that gave the requested triangle count
};

// The Z-map of `simulation` as a closed solid on z = 0 whose top has about `triangles`, or
// more where that would take a chord tolerance above 0.5 mm. The centre of every gouge is a
// vertex.
Workpiece workpiece_mesh(const MillingSimulation& simulation, std::size_t triangles);

// Mills the part with `stages` in order on a Z-map at the size's resolution, and hands the
// simulation to `visit` after each stage.
void mill_part(const MouldCore& part, double size, const std::vector<MillingStage>& stages,
               const std::function<void(const MillingStage&, const MillingSimulation&)>& visit);

// Triangles a stage's workpiece has at a size.
std::size_t workpiece_triangles(const MillingStage& stage, double size);

}  // namespace ncv::gen
