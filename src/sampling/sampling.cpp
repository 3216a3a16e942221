#include "sampling/sampling.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "util/block_offsets.hpp"
#include "util/error.hpp"
#include "util/ordered_reduce.hpp"
#include "util/round_nonnegative.hpp"

namespace ncv {
namespace {

constexpr std::size_t kTriangleBlock = 1 << 14;  // ordered_reduce's blocks

// A tiny step gives up to 2 * 10^18 samples per triangle: sample counts saturate rather than
// wrap to a count small enough to pass the memory guard or to size arrays too small.
void saturating_add(std::uint64_t& sum, std::uint64_t value) {
  if (__builtin_add_overflow(sum, value, &sum)) sum = std::numeric_limits<std::uint64_t>::max();
}

// The samples of the triangles' lattices that are not mesh vertices, saturated.
std::uint64_t interior_sample_count(const std::vector<std::uint32_t>& sizes) {
  return ordered_reduce(
      sizes.size(), kTriangleBlock, std::uint64_t{0},
      [&](std::size_t begin, std::size_t end) {
        std::uint64_t interior = 0;
        for (std::size_t t = begin; t < end; ++t) {
          saturating_add(interior, lattice_interior_count(sizes[t]));
        }
        return interior;
      },
      saturating_add);
}

// Lattice coordinates of corner k of a size-n lattice: A = (0,0), B = (n-1,0), C = (0,n-1).
std::pair<std::uint32_t, std::uint32_t> corner_lattice_coordinates(int k, std::uint32_t n) {
  if (k == 1) return {n - 1, 0};
  if (k == 2) return {0, n - 1};
  return {0, 0};
}

// Numbers the mesh vertices that belong to a sampled triangle: they are samples
// 0 .. count-1, each owned by its lowest-index sampled triangle (found in parallel by an
// atomic minimum, so the result does not depend on the thread count). Returns the owners.
std::vector<std::uint32_t> number_vertex_samples(SampleSet& set) {
  const Mesh& mesh = set.mesh;
  set.vertex_sample.assign(mesh.vertex_count(), kNoSample);
  std::vector<std::uint32_t> owner_of_vertex(mesh.vertex_count(), kNoSample);
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, mesh.triangle_count(), 4096), [&](const auto& r) {
        for (std::size_t t = r.begin(); t != r.end(); ++t) {
          if (set.lattice_sizes[t] == 0) continue;
          const auto triangle = static_cast<std::uint32_t>(t);
          for (const std::uint32_t v : mesh.triangles[t]) {
            std::atomic_ref<std::uint32_t> owner(owner_of_vertex[v]);
            std::uint32_t seen = owner.load(std::memory_order_relaxed);
            while (triangle < seen &&
                   !owner.compare_exchange_weak(seen, triangle, std::memory_order_relaxed)) {
            }
          }
        }
      });
  const Buffer<std::uint32_t> number = block_offsets<std::uint32_t>(
      mesh.vertex_count(), [&](std::size_t v) { return owner_of_vertex[v] != kNoSample ? 1 : 0; });
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mesh.vertex_count(), 1 << 14),
                    [&](const auto& r) {
                      for (std::size_t v = r.begin(); v != r.end(); ++v) {
                        if (owner_of_vertex[v] != kNoSample) {
                          set.vertex_sample[v] = number[v];
                        }
                      }
                    });
  return owner_of_vertex;
}

// The vertex samples the set holds, at their lattice corner of their owning triangle; each
// vertex writes its own sample, so in parallel.
void fill_vertex_samples(SampleSet& set, const std::vector<std::uint32_t>& owner_of_vertex) {
  const Mesh& mesh = set.mesh;
  const std::uint64_t end = set.first_sample + set.sample_count();
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, mesh.vertex_count(), 1 << 14), [&](const auto& r) {
        for (std::size_t v = r.begin(); v != r.end(); ++v) {
          const std::uint64_t s = set.vertex_sample[v];
          if (s == kNoSample || s < set.first_sample || s >= end) continue;
          const std::uint32_t t = owner_of_vertex[v];
          const auto& corners = mesh.triangles[t];
          const int corner = corners[0] == v ? 0 : corners[1] == v ? 1 : 2;  // the first that is v
          const auto [i, j] = corner_lattice_coordinates(corner, set.lattice_sizes[t]);
          const std::uint64_t k = s - set.first_sample;
          set.positions[k] = mesh.vertices[v];
          set.owner[k] = t;
          set.lattice_i[k] = i;
          set.lattice_j[k] = j;
        }
      });
}

bool is_corner(std::uint32_t i, std::uint32_t j, std::uint32_t n) {
  return (i == 0 && j == 0) || (i == n - 1 && j == 0) || (i == 0 && j == n - 1);
}

// Writes the non-corner lattice points of triangle t, samples first_interior_sample[t] on in
// row-major order, that the set holds.
void fill_triangle_samples(SampleSet& set, std::size_t t) {
  const std::uint32_t n = set.lattice_sizes[t];
  if (n < 3) return;
  const std::uint64_t first = set.first_interior_sample[t];
  const std::uint64_t begin = set.first_sample, end = set.first_sample + set.sample_count();
  if (first >= end || first + lattice_interior_count(n) <= begin) return;
  const LatticeFrame frame(set.mesh, t, n);
  std::uint64_t s = first;
  for (std::uint32_t i = 0; i < n; ++i) {
    for (std::uint32_t j = 0; j + i < n; ++j) {
      if (is_corner(i, j, n)) continue;
      if (s >= begin && s < end) {
        const std::uint64_t k = s - begin;
        set.positions[k] = frame.at(i, j);
        set.owner[k] = static_cast<std::uint32_t>(t);
        set.lattice_i[k] = i;
        set.lattice_j[k] = j;
      }
      ++s;
    }
  }
}

}  // namespace

LatticeFrame::LatticeFrame(const Mesh& mesh, std::size_t t, std::uint32_t n)
    : a(mesh.corner(t, 0)),
      e1((mesh.corner(t, 1) - a) / static_cast<double>(n - 1)),
      e2((mesh.corner(t, 2) - a) / static_cast<double>(n - 1)) {}

Vec3 lattice_point(const Mesh& mesh, std::size_t t, std::uint32_t n, std::uint32_t i,
                   std::uint32_t j) {
  if (i == 0 && j == 0) return mesh.corner(t, 0);
  if (i == n - 1 && j == 0) return mesh.corner(t, 1);
  if (i == 0 && j == n - 1) return mesh.corner(t, 2);
  return LatticeFrame(mesh, t, n).at(i, j);
}

std::uint32_t lattice_size(double area, double step) {
  const double n_prime = std::sqrt(0.25 + 2.0 * area / (step * step)) - 0.5;
  // Caps keep the conversion defined; the sample-count guard refuses such steps anyway.
  if (!(n_prime < 2.0e9)) return 2'000'000'000u;
  return static_cast<std::uint32_t>(round_nonnegative(n_prime));  // n_prime >= 0
}

std::uint64_t SampleSet::sample_at(std::size_t t, std::uint32_t i, std::uint32_t j) const {
  const std::uint64_t n = lattice_sizes[t];
  if (i == 0 && j == 0) return vertex_sample[mesh.triangles[t][0]];
  if (i == n - 1 && j == 0) return vertex_sample[mesh.triangles[t][1]];
  if (i == 0 && j == n - 1) return vertex_sample[mesh.triangles[t][2]];
  // Row-major rank of (i, j) minus the corners that precede it: (0,0) always, and
  // (0,n-1) once past row 0.
  const std::uint64_t rank = i * n - i * (i - 1) / 2 + j;
  return first_interior_sample[t] + rank - (i == 0 ? 1 : 2);
}

// One pass computes each triangle's area once for both the sizes and the report's counts,
// in blocks so that the area sum does not depend on the thread count.
SamplingPlan plan_sampling(const Mesh& mesh, double step, SamplingScheme scheme) {
  SamplingPlan plan;
  plan.step = step;
  plan.scheme = scheme;
  plan.lattice_sizes.resize(mesh.triangle_count());
  plan.triangle_areas.resize(mesh.triangle_count());
  std::vector<std::uint32_t>& sizes = plan.lattice_sizes;
  plan.counts = ordered_reduce(
      sizes.size(), kTriangleBlock, SamplingReport{},
      [&](std::size_t begin, std::size_t end) {
        SamplingReport part;
        for (std::size_t t = begin; t < end; ++t) {
          const double area = triangle_area(mesh, t);
          plan.triangle_areas[t] = area;
          const std::uint32_t n = lattice_size(area, step);
          sizes[t] = n >= 2 ? n : scheme == SamplingScheme::all ? 2u : 0u;
          if (n < 2) ++part.small_triangles;
          if (area == 0) ++part.degenerate_triangles;
          part.surface_area += area;
        }
        return part;
      },
      [](SamplingReport& sum, const SamplingReport& part) {
        sum.small_triangles += part.small_triangles;
        sum.degenerate_triangles += part.degenerate_triangles;
        sum.surface_area += part.surface_area;
      });
  return plan;
}

std::uint64_t predicted_sample_count(const Mesh& mesh, const SamplingPlan& plan) {
  const std::vector<std::uint32_t>& sizes = plan.lattice_sizes;
  std::vector<std::uint8_t> vertex_used(mesh.vertex_count(), 0);
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, sizes.size(), kTriangleBlock), [&](const auto& r) {
        for (std::size_t t = r.begin(); t != r.end(); ++t) {
          if (sizes[t] == 0) continue;
          for (const std::uint32_t v : mesh.triangles[t]) {
            std::atomic_ref<std::uint8_t>(vertex_used[v]).store(1, std::memory_order_relaxed);
          }
        }
      });
  std::uint64_t count = interior_sample_count(sizes);
  saturating_add(count, static_cast<std::uint64_t>(
                            std::count(vertex_used.begin(), vertex_used.end(), std::uint8_t{1})));
  return count;
}

SampleSet sample_mesh(Mesh workpiece, double step, SamplingScheme scheme, SamplingReport* report) {
  SamplingPlan plan = plan_sampling(workpiece, step, scheme);
  return sample_mesh(std::move(workpiece), std::move(plan), report);
}

SampleSet sample_mesh(Mesh mesh, SamplingPlan plan, SamplingReport* report,
                      const std::optional<Shard>& shard) {
  SampleSet set;
  set.mesh = std::move(mesh);
  set.step = plan.step;
  set.scheme = plan.scheme;
  set.mesh_hash = mesh_hash(set.mesh);
  set.lattice_sizes = std::move(plan.lattice_sizes);
  set.triangle_areas = std::move(plan.triangle_areas);

  const std::vector<std::uint32_t> owner_of_vertex = number_vertex_samples(set);
  const std::uint64_t vertex_samples =
      std::count_if(set.vertex_sample.begin(), set.vertex_sample.end(),
                    [](std::uint32_t s) { return s != kNoSample; });
  // Only reachable past the memory guard (--force): a saturated count would size the arrays
  // too small for the lattice written into them. Checked first, so the offsets cannot wrap.
  std::uint64_t next = interior_sample_count(set.lattice_sizes);
  saturating_add(next, vertex_samples);
  if (next == std::numeric_limits<std::uint64_t>::max()) {
    throw UsageError(
        fmt::format("sampling at step {} would give more than 2^64 samples", set.step));
  }
  // The interior samples follow the vertex samples, triangle after triangle.
  set.first_interior_sample = block_offsets(
      set.lattice_sizes.size(),
      [&](std::size_t t) { return lattice_interior_count(set.lattice_sizes[t]); }, vertex_samples);
  set.first_interior_sample.pop_back();
  set.total_samples = next;
  const SampleRange range = shard ? shard_range(next, *shard) : SampleRange{0, next};
  set.shard = shard;
  set.first_sample = range.begin;
  set.positions.resize(range.size());
  set.owner.resize(range.size());
  set.lattice_i.resize(range.size());
  set.lattice_j.resize(range.size());
  fill_vertex_samples(set, owner_of_vertex);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, set.lattice_sizes.size(), 1024),
                    [&](const auto& r) {
                      for (std::size_t t = r.begin(); t != r.end(); ++t) {
                        fill_triangle_samples(set, t);
                      }
                    });

  if (report) {
    *report = plan.counts;
    report->triangles = set.mesh.triangle_count();
    report->samples = set.total_samples;
  }
  return set;
}

}  // namespace ncv
