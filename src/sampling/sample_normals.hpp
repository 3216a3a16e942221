// The workpiece's own normal at every sample, which the paper's sign rule (--sign paper)
// uses: the owning triangle's unit normal for a lattice point inside a triangle, the
// area-weighted mean of the incident triangles' normals for a mesh vertex.
#pragma once

#include <vector>

#include "sampling/sampling.hpp"

namespace ncv {

std::vector<Vec3> sample_normals(const SampleSet& samples);
// Per mesh vertex: the area-weighted sum of its triangles' normals (not normalised).
std::vector<Vec3> vertex_normal_sums(const Mesh& mesh);

}  // namespace ncv
