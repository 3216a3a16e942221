// The sub-triangles of the sampling lattice (docs/METHOD.md "Error measures"): a triangle with
// lattice size n splits into (n-1)^2 sub-triangles of equal area |T|/(n-1)^2, the
// "upward" (i,j),(i+1,j),(i,j+1) and the "downward" (i+1,j),(i+1,j+1),(i,j+1) ones.
// Corners are listed counter-clockwise in (i, j), so every sub-triangle keeps the
// orientation of its mesh triangle.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "geometry/linear_patch.hpp"
#include "sampling/sampling.hpp"
#include "util/buffer.hpp"

namespace ncv {

constexpr std::uint64_t lattice_triangle_count(std::uint64_t n) {
  return n < 2 ? 0 : (n - 1) * (n - 1);
}

double lattice_triangle_area(const SampleSet& samples, std::size_t t);

// Calls visit(a, b, c) with the sample indices of every sub-triangle of triangle t (none
// when t is not sampled), upward and downward ones interleaved along each row.
template <class Visit>
void for_each_lattice_triangle(const SampleSet& samples, std::size_t t, Visit&& visit) {
  const std::uint32_t n = samples.lattice_sizes[t];
  for (std::uint32_t i = 0; i + 1 < n; ++i) {
    // Row i has n-i points, row i+1 one fewer.
    std::uint64_t low = samples.sample_at(t, i, 0);
    std::uint64_t high = samples.sample_at(t, i + 1, 0);
    for (std::uint32_t j = 0; i + j + 1 < n; ++j) {
      const std::uint64_t next_low = samples.sample_at(t, i, j + 1);
      visit(low, high, next_low);
      if (i + j + 2 < n) {
        const std::uint64_t next_high = samples.sample_at(t, i + 1, j + 1);
        visit(high, next_high, next_low);
        high = next_high;
      }
      low = next_low;
    }
  }
}

// Every sub-triangle of every sampled triangle as a linear patch of the distances d (one
// per sample), triangle by triangle in mesh order. Filled in parallel, each patch written
// once (no serial zero-fill first).
Buffer<LinearPatch> lattice_patches(const SampleSet& samples, std::span<const double> d);

}  // namespace ncv
