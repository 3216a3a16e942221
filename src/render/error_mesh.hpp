// A mesh carrying one error value per vertex, the input of the coloured PLY.
#pragma once

#include <span>
#include <vector>

#include "mesh/mesh.hpp"
#include "sampling/sampling.hpp"
#include "statistics/error_regions.hpp"

namespace ncv {

struct ErrorMesh {
  Mesh mesh;
  std::vector<double> values;          // per vertex; NaN where no sample lies
  std::vector<std::uint32_t> regions;  // per vertex: its out-of-tolerance region (k + 1 for
                                       // the report's k-th region), kNoRegion elsewhere
};

// sample_region (per sample, statistics/error_regions.hpp RegionMap) may be empty: no
// vertex is in a region then.
//
// The workpiece mesh itself, each vertex with the distance of its sample. A vertex no
// sampled triangle touches (scheme II) gets NaN: borrowing a value from elsewhere would
// paint a measurement that was never made. Lattice points inside triangles are not shown.
ErrorMesh workpiece_error_mesh(const SampleSet& samples, std::span<const double> d,
                               std::span<const std::uint32_t> sample_region = {});

// The sampling lattice as a mesh: every sample a vertex (numbered as the samples), every
// lattice sub-triangle a face, so each sample's error is visible. Triangles that share an
// edge keep their own lattice points on it, so the mesh is not welded along such edges.
// Unsampled triangles (scheme II) are kept as they are, with NaN at corners no sample
// covers, so the shape stays whole.
ErrorMesh lattice_error_mesh(const SampleSet& samples, std::span<const double> d,
                             std::span<const std::uint32_t> sample_region = {});

}  // namespace ncv
