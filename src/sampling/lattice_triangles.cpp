#include "sampling/lattice_triangles.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace ncv {

double lattice_triangle_area(const SampleSet& samples, std::size_t t) {
  const double steps = samples.lattice_sizes[t] - 1.0;
  return triangle_area(samples.mesh, t) / (steps * steps);
}

Buffer<LinearPatch> lattice_patches(const SampleSet& samples, std::span<const double> d) {
  const std::size_t triangles = samples.lattice_sizes.size();
  std::vector<std::uint64_t> first(triangles + 1, 0);
  for (std::size_t t = 0; t < triangles; ++t) {
    first[t + 1] = first[t] + lattice_triangle_count(samples.lattice_sizes[t]);
  }
  Buffer<LinearPatch> patches(first[triangles]);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, triangles, 1024), [&](const auto& range) {
    for (std::size_t t = range.begin(); t != range.end(); ++t) {
      if (samples.lattice_sizes[t] < 2) continue;
      const double area = lattice_triangle_area(samples, t);
      LinearPatch* out = patches.data() + first[t];
      for_each_lattice_triangle(samples, t, [&](std::uint64_t a, std::uint64_t b, std::uint64_t c) {
        *out++ = make_linear_patch(area, d[a], d[b], d[c]);
      });
    }
  });
  return patches;
}

}  // namespace ncv
