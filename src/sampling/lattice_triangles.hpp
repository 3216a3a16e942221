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
#include "geometry/patch_source.hpp"
#include "sampling/sampling.hpp"

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

// Every sub-triangle of every sampled triangle as a linear patch of the distances d (one per
// sample), triangle by triangle in mesh order, made on demand a range at a time. The
// statistics make them in three passes; stored, they were 32 bytes a patch of fresh pages
// (77 MB for the paper-scale finishing part, 92 MB for the uncut slot), which this machine's
// kernel clears at first touch: slower than making them again (docs/PERFORMANCE.md).
class LatticePatches final : public PatchSource {
 public:
  LatticePatches(const SampleSet& samples, std::span<const double> d);

  std::size_t size() const override { return size_; }
  std::span<const LinearPatch> range(std::size_t begin, std::size_t end,
                                     std::span<LinearPatch> scratch) const override;

 private:
  // Patch k * kStartStride lies in `triangle`, the skip-th of its patches. Every range of
  // the statistics' passes starts at such a patch.
  static constexpr std::uint64_t kStartStride = std::uint64_t{1} << 13;
  struct Start {
    std::size_t triangle;
    std::uint64_t skip;
  };

  std::vector<Start> find_starts();  // sets size_
  template <bool kVerticesInOrder>
  std::span<const LinearPatch> range_of(std::size_t begin, std::size_t end,
                                        std::span<LinearPatch> scratch) const;
  void make_patches(std::size_t t, std::uint64_t skip, std::uint64_t count, LinearPatch* out,
                    std::vector<double>& rows) const;

  const SampleSet& samples_;
  std::span<const double> d_;
  std::uint64_t size_ = 0;
  std::vector<Start> starts_;
  bool vertices_in_order_;  // vertex v's sample is sample v, for every v
};

}  // namespace ncv
