#include "sampling/lattice_triangles.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "util/block_offsets.hpp"

namespace ncv {

double lattice_triangle_area(const SampleSet& samples, std::size_t t) {
  const double steps = samples.lattice_sizes[t] - 1.0;
  return samples.triangle_areas[t] / (steps * steps);
}

Buffer<LinearPatch> lattice_patches(const SampleSet& samples, std::span<const double> d) {
  const std::size_t triangles = samples.lattice_sizes.size();
  const Buffer<std::uint64_t> first = block_offsets(
      triangles, [&](std::size_t t) { return lattice_triangle_count(samples.lattice_sizes[t]); });
  Buffer<LinearPatch> patches(first[triangles]);
  const Mesh& mesh = samples.mesh;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, triangles, 1024), [&](const auto& range) {
    for (std::size_t t = range.begin(); t != range.end(); ++t) {
      const std::uint32_t n = samples.lattice_sizes[t];
      if (n < 2) continue;
      LinearPatch* out = patches.data() + first[t];
      if (n == 2) {  // most triangles of a fine mesh: one sub-triangle, the corners' samples
        const auto& corner = mesh.triangles[t];
        *out = make_linear_patch(samples.triangle_areas[t], d[samples.vertex_sample[corner[0]]],
                                 d[samples.vertex_sample[corner[1]]],
                                 d[samples.vertex_sample[corner[2]]]);
        continue;
      }
      const double area = lattice_triangle_area(samples, t);
      for_each_lattice_triangle(samples, t, [&](std::uint64_t a, std::uint64_t b, std::uint64_t c) {
        *out++ = make_linear_patch(area, d[a], d[b], d[c]);
      });
    }
  });
  return patches;
}

}  // namespace ncv
