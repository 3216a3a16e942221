#include "sampling/lattice_triangles.hpp"

#include <algorithm>
#include <vector>

#include "util/block_offsets.hpp"

namespace ncv {

double lattice_triangle_area(const SampleSet& samples, std::size_t t) {
  const double steps = samples.lattice_sizes[t] - 1.0;
  return samples.triangle_areas[t] / (steps * steps);
}

namespace {

// The distances at lattice row i of triangle t (lattice size n): its n - i points in j
// order. A row's points other than the triangle's corners are its own samples, numbered
// consecutively (sampling.hpp), so each row is a corner or two and one run of the array.
void row_distances(const SampleSet& samples, std::span<const double> d, std::size_t t,
                   std::uint32_t n, std::uint32_t i, double* row) {
  const auto run = [&](std::uint32_t j, std::uint32_t count) {
    const std::span<const double> own = d.subspan(samples.sample_at(t, i, j), count);
    std::copy(own.begin(), own.end(), row + j);
  };
  if (i == 0) {
    row[0] = d[samples.sample_at(t, 0, 0)];
    run(1, n - 2);
    row[n - 1] = d[samples.sample_at(t, 0, n - 1)];
  } else if (i == n - 1) {
    row[0] = d[samples.sample_at(t, i, 0)];
  } else {
    run(0, n - i);
  }
}

// Whether vertex v's sample is sample v for every vertex: then a corner's distance is read
// without vertex_sample (one random load a corner fewer where the triangles come in random
// order).
bool vertex_samples_in_order(const SampleSet& samples) {
  const std::span<const std::uint32_t> numbers = samples.vertex_sample;
  return samples.first_sample == 0 &&
         std::all_of(numbers.begin(), numbers.end(),
                     [&, v = std::uint32_t{0}](std::uint32_t s) mutable { return s == v++; });
}

}  // namespace

// Where each patch whose index is a multiple of kStartStride lies: its triangle and its
// place among that triangle's patches, from the triangles' patch offsets (two parallel
// passes, without storing an offset a triangle).
std::vector<LatticePatches::Start> LatticePatches::find_starts() {
  const auto patches_of = [&](std::size_t t) {
    return lattice_triangle_count(samples_.lattice_sizes[t]);
  };
  const std::size_t triangles = samples_.lattice_sizes.size();
  const std::vector<std::uint64_t> block_first = block_starts<std::uint64_t>(triangles, patches_of);
  size_ = block_first.back();
  std::vector<Start> starts((size_ + kStartStride - 1) / kStartStride);
  for_each_offset(triangles, patches_of, block_first, [&](std::size_t t, std::uint64_t first) {
    const std::uint64_t end = first + patches_of(t);
    for (std::uint64_t k = (first + kStartStride - 1) / kStartStride; k * kStartStride < end; ++k) {
      starts[k] = {t, k * kStartStride - first};
    }
  });
  return starts;
}

LatticePatches::LatticePatches(const SampleSet& samples, std::span<const double> d)
    : samples_(samples),
      d_(d),
      starts_(find_starts()),
      vertices_in_order_(vertex_samples_in_order(samples)) {}

std::span<const LinearPatch> LatticePatches::range(std::size_t begin, std::size_t end,
                                                   std::span<LinearPatch> scratch) const {
  return vertices_in_order_ ? range_of<true>(begin, end, scratch)
                            : range_of<false>(begin, end, scratch);
}

template <bool kVerticesInOrder>
std::span<const LinearPatch> LatticePatches::range_of(std::size_t begin, std::size_t end,
                                                      std::span<LinearPatch> scratch) const {
  if (begin == end) return {};
  // The triangle holding patch `begin`, from the stride point at or before it.
  const Start& start = starts_[begin / kStartStride];
  std::size_t t = start.triangle;
  std::uint64_t skip = start.skip + begin % kStartStride;
  while (skip >= lattice_triangle_count(samples_.lattice_sizes[t])) {
    skip -= lattice_triangle_count(samples_.lattice_sizes[t]);
    ++t;
  }
  LinearPatch* out = scratch.data();
  std::vector<double> rows;  // two lattice rows, for make_patches
  for (std::uint64_t at = begin; at < end; ++t, skip = 0) {
    const std::uint32_t n = samples_.lattice_sizes[t];
    if (n == 2) {  // most triangles of a fine mesh: one patch, the corners'
      const auto& corner = samples_.mesh.triangles[t];
      const auto at_corner = [&](int k) {
        return d_[kVerticesInOrder ? corner[k] : samples_.vertex_sample[corner[k]]];
      };
      *out++ =
          make_linear_patch(samples_.triangle_areas[t], at_corner(0), at_corner(1), at_corner(2));
      ++at;
    } else if (n > 2) {
      const std::uint64_t count = std::min(lattice_triangle_count(n) - skip, end - at);
      make_patches(t, skip, count, out, rows);
      out += count;
      at += count;
    }
  }
  return scratch.first(end - begin);
}

// Sub-triangles [skip, skip + count) of triangle t in for_each_lattice_triangle's order: row
// i holds 2 (n - 1 - i) - 1 of them, upward and downward ones alternating.
void LatticePatches::make_patches(std::size_t t, std::uint64_t skip, std::uint64_t count,
                                  LinearPatch* out, std::vector<double>& rows) const {
  const std::uint32_t n = samples_.lattice_sizes[t];
  const double area = lattice_triangle_area(samples_, t);
  std::uint32_t i = 0;
  for (std::uint64_t in_row = 2 * std::uint64_t{n} - 3; skip >= in_row; in_row -= 2) {
    skip -= in_row;
    ++i;
  }
  if (rows.size() < 2 * std::size_t{n}) rows.resize(2 * std::size_t{n});
  double* low = rows.data();
  double* high = low + n;
  row_distances(samples_, d_, t, n, i, low);
  for (; count > 0; ++i, skip = 0) {
    row_distances(samples_, d_, t, n, i + 1, high);
    const std::uint64_t in_row = 2 * std::uint64_t{n - 1 - i} - 1;
    for (std::uint64_t p = skip; p < in_row && count > 0; ++p, --count) {
      const std::uint64_t j = p / 2;
      *out++ = p % 2 == 0 ? make_linear_patch(area, low[j], high[j], low[j + 1])
                          : make_linear_patch(area, high[j], high[j + 1], low[j + 1]);
    }
    std::swap(low, high);
  }
}

}  // namespace ncv
