// The decimated family: the same mould core and the same simulated Z-maps as the RTIN parts,
// meshed a second, independent way, the way many CAM systems export: a fine triangulation of
// the heights reduced by quadric-error decimation (decimation.hpp) to the size's triangle
// count. Its triangles are no longer right isosceles on a bintree: collapses leave fans,
// slivers along steps and long triangles across flats, as a decimater does.
//
// The full Z-map grid (12.6 M triangles at the large size) would take minutes to decimate
// with OpenMesh; the fine triangulation is instead an RTIN with `refinement` times the target
// count, at a chord tolerance a fraction of the target's.
#pragma once

#include <cstddef>
#include <vector>

#include "mesh/mesh.hpp"
#include "ncgen/grid.hpp"
#include "ncgen/milling_simulation.hpp"
#include "ncgen/mould_core.hpp"

namespace ncv::gen {

// The nominal of the decimated family: about as many triangles as the paper's CAD export of
// its mould core.
constexpr std::size_t decimated_nominal_triangles = 17'600;

struct DecimatedOptions {
  // Fine triangles per target triangle before decimation. At 2 the large finishing part shares
  // 14 % of its triangles with the RTIN one of its size (at 3, 17 %) and decimates in 25-35 s;
  // each further unit costs about as much again.
  double refinement = 2;
  // Decimation's bound on each removed sample's distance to the surface, as a multiple of the
  // chord tolerance an RTIN of the target count needs: 1 decimates as accurately as the RTIN.
  double tolerance_factor = 1;
};

struct DecimatedSolid {
  ncv::Mesh mesh;                  // closed, outward-oriented; walls and bottom as the RTIN parts'
  std::size_t fine_triangles = 0;  // the fine RTIN's top
  float fine_tolerance = 0;        // its chord tolerance, mm
  double tolerance = 0;            // decimation's distance bound, mm
  std::size_t collapses = 0;
};

// A closed solid of `heights` with about `triangles` triangles in all, or more where the
// decimation would leave samples farther than options.tolerance_factor * chord_tolerance; the
// samples in `keep` stay vertices. `errors` are the heights' propagated chord errors
// (rtin.hpp), with infinity at the samples to keep; `chord_tolerance` is the RTIN's for this
// part, which sets the fine RTIN's size too (refinement times the larger of `triangles` and
// that RTIN's count).
DecimatedSolid decimated_height_solid(const Grid& grid, const std::vector<float>& heights,
                                      const std::vector<float>& errors,
                                      const std::vector<std::uint32_t>& keep, std::size_t triangles,
                                      float chord_tolerance, const DecimatedOptions& options);

// The Z-map after the simulation's last stage, every gouge centre a vertex; the chord
// tolerance as the RTIN workpiece's (workpiece.hpp), at most 0.5 mm.
DecimatedSolid decimated_workpiece_mesh(const MillingSimulation& simulation, std::size_t triangles,
                                        const DecimatedOptions& options = {});

// The mould core sampled at 0.078 mm, as the RTIN nominal is.
DecimatedSolid decimated_nominal_mesh(const MouldCore& part,
                                      std::size_t triangles = decimated_nominal_triangles,
                                      const DecimatedOptions& options = {});

}  // namespace ncv::gen
