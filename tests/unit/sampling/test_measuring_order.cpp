// The order the distance step measures a sample set in: none for a mesh written neighbour
// after neighbour, and for one whose facets are shuffled every own sample once, triangle by
// triangle, the triangles in Morton order of their first corner, whatever the threads.
#include <catch2/catch.hpp>

#include <tbb/global_control.h>

#include <algorithm>
#include <vector>

#include "geometry/morton_cells.hpp"
#include "nominal_fixtures.hpp"
#include "sampling/measuring_order.hpp"
#include "sampling/sampling.hpp"

namespace {

namespace fx = ncv::fixtures;

// A torus of 40,000 triangles sampled at three own samples a triangle (lattices of size 3):
// 120,000 own samples.
constexpr double kStep = 0.25;
ncv::Mesh torus() {
  return fx::torus(40, 10, 200, 100);
}

ncv::SampleSet sampled(ncv::Mesh mesh) {
  ncv::SampleSet samples = ncv::sample_mesh(std::move(mesh), kStep, ncv::SamplingScheme::all);
  REQUIRE(samples.total_samples - samples.first_interior_sample[0] >= ncv::kLeastScatteredSamples);
  return samples;
}

// The mean distance between the samples at consecutive places of the numbers given.
double mean_step(const ncv::SampleSet& samples, const std::vector<std::uint32_t>& numbers) {
  double sum = 0;
  for (std::size_t k = 1; k < numbers.size(); ++k) {
    sum += ncv::norm(samples.positions[numbers[k]] - samples.positions[numbers[k - 1]]);
  }
  return sum / static_cast<double>(numbers.size() - 1);
}

}  // namespace

TEST_CASE("a sample set numbered neighbour after neighbour keeps its order", "[sampling]") {
  const ncv::SampleSet samples = sampled(torus());
  CHECK_FALSE(ncv::own_samples_scattered(samples));
  CHECK(ncv::measuring_order(samples).empty());
}

TEST_CASE("the own samples of shuffled facets are measured triangle by triangle in space",
          "[sampling]") {
  const ncv::SampleSet samples = sampled(fx::shuffled_facets(torus(), 5));
  REQUIRE(ncv::own_samples_scattered(samples));
  const ncv::Buffer<std::uint32_t> order = ncv::measuring_order(samples);
  const std::uint64_t begin = samples.first_interior_sample[0];
  REQUIRE(order.size() == samples.total_samples - begin);

  // Every own sample once.
  std::vector<std::uint32_t> sorted(order.begin(), order.end());
  std::sort(sorted.begin(), sorted.end());
  bool each_once = true;
  for (std::size_t k = 0; k < sorted.size(); ++k) each_once &= sorted[k] == begin + k;
  CHECK(each_once);

  // Triangle by triangle, each one's samples in their order, the triangles by their first
  // corner's cell.
  const ncv::MortonCells cells(ncv::bounding_box(samples.mesh), 5);
  bool runs = true, cells_ascend = true;
  std::uint32_t last_cell = 0;
  for (std::size_t k = 0; k < order.size();) {
    const std::uint32_t t = samples.owner[order[k]];
    const std::uint64_t first = samples.first_interior_sample[t];
    const std::uint64_t count = ncv::lattice_interior_count(samples.lattice_sizes[t]);
    for (std::uint64_t s = 0; s < count; ++s) runs &= order[k + s] == first + s;
    const std::uint32_t cell = cells.cell(samples.mesh.corner(t, 0));
    cells_ascend &= cell >= last_cell;
    last_cell = cell;
    k += count;
  }
  CHECK(runs);
  CHECK(cells_ascend);

  // Consecutive places lie far closer together than consecutive numbers.
  std::vector<std::uint32_t> numbered(order.size());
  for (std::size_t k = 0; k < numbered.size(); ++k) {
    numbered[k] = static_cast<std::uint32_t>(begin + k);
  }
  const std::vector<std::uint32_t> ordered(order.begin(), order.end());
  CHECK(mean_step(samples, ordered) < 0.1 * mean_step(samples, numbered));

  for (const int threads : {1, 2, 3}) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    CHECK(ncv::measuring_order(samples) == order);
  }
}

TEST_CASE("a shard's samples and a few own samples keep their order", "[sampling]") {
  const ncv::Mesh shuffled = fx::shuffled_facets(torus(), 5);
  ncv::SamplingPlan plan = ncv::plan_sampling(shuffled, kStep, ncv::SamplingScheme::all);
  const ncv::SampleSet shard =
      ncv::sample_mesh(shuffled, std::move(plan), nullptr, ncv::Shard{1, 2});
  CHECK_FALSE(ncv::own_samples_scattered(shard));
  CHECK(ncv::measuring_order(shard).empty());
  // Fewer own samples than kLeastScatteredSamples: one a triangle at most.
  const ncv::SampleSet coarse =
      ncv::sample_mesh(fx::shuffled_facets(torus(), 5), 2.0, ncv::SamplingScheme::all);
  REQUIRE(coarse.total_samples - coarse.first_interior_sample[0] < ncv::kLeastScatteredSamples);
  CHECK(ncv::measuring_order(coarse).empty());
}
