// The lattice's sub-triangles as linear patches, made a range at a time (LatticePatches):
// every range, wherever it starts and ends, is the same patches as the sub-triangles that
// for_each_lattice_triangle lists, in its order and to the bit.
#include <catch2/catch.hpp>

#include <bit>
#include <cstdint>
#include <random>
#include <vector>

#include "sampling/lattice_triangles.hpp"
#include "sampling/sampling.hpp"

using namespace ncv;

namespace {

// Triangles of very different sizes (lattices of 2 up to dozens of points a side), some of
// them degenerate, and vertices shared in any order. With `first_unused`, vertex 0 is on no
// triangle: it has no sample, and vertex v's sample is v - 1 (LatticePatches then reads the
// corners through vertex_sample; otherwise vertex v's sample is v).
Mesh mixed_mesh(std::mt19937& rng, bool first_unused) {
  std::uniform_real_distribution<double> coordinate(0, 1);
  std::uniform_real_distribution<double> scale(0.01, 4);
  Mesh mesh;
  for (int v = 0; v < 60; ++v) {
    const double s = scale(rng);
    mesh.vertices.push_back({s * coordinate(rng), s * coordinate(rng), s * coordinate(rng)});
  }
  const std::uint32_t first = first_unused ? 1 : 0;
  std::uniform_int_distribution<std::uint32_t> vertex(first, 59);
  while (mesh.triangles.size() < 120) {
    const Triangle t{vertex(rng), vertex(rng), vertex(rng)};
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) mesh.triangles.push_back(t);
  }
  mesh.vertices.push_back(mesh.vertices[first]);  // a degenerate triangle: two equal corners
  mesh.triangles.push_back({first, 60, first + 1});
  return mesh;
}

std::vector<LinearPatch> listed_patches(const SampleSet& samples, std::span<const double> d) {
  std::vector<LinearPatch> patches;
  for (std::size_t t = 0; t < samples.mesh.triangle_count(); ++t) {
    const double area = lattice_triangle_area(samples, t);
    for_each_lattice_triangle(samples, t, [&](std::uint64_t a, std::uint64_t b, std::uint64_t c) {
      patches.push_back(make_linear_patch(area, d[a], d[b], d[c]));
    });
  }
  return patches;
}

bool same_bits(const LinearPatch& x, const LinearPatch& y) {
  const auto bits = [](double v) { return std::bit_cast<std::uint64_t>(v); };
  return bits(x.area) == bits(y.area) && bits(x.lo) == bits(y.lo) && bits(x.mid) == bits(y.mid) &&
         bits(x.hi) == bits(y.hi);
}

}  // namespace

TEST_CASE("lattice patches made from any range are the listed sub-triangles", "[sampling]") {
  std::mt19937 rng(23);
  for (const bool first_unused : {false, true})
    for (const SamplingScheme scheme : {SamplingScheme::all, SamplingScheme::paper_ii}) {
      const SampleSet samples = sample_mesh(mixed_mesh(rng, first_unused), 0.05, scheme);
      INFO((first_unused ? "vertex 0 unused" : "every vertex used")
           << ", scheme " << static_cast<int>(scheme));
      std::uniform_real_distribution<double> error(-1, 1);
      std::vector<double> d(samples.sample_count());
      for (double& v : d) v = error(rng);
      d[0] = -0.0;  // signed zeros keep their place in the corner order
      d[1] = 0.0;
      const std::vector<LinearPatch> expected = listed_patches(samples, d);
      const LatticePatches patches(samples, d);
      REQUIRE(patches.size() == expected.size());
      REQUIRE(expected.size() > 10000);
      std::vector<LinearPatch> scratch(expected.size());
      std::uniform_int_distribution<std::size_t> position(0, expected.size());
      for (int trial = 0; trial < 300; ++trial) {
        std::size_t begin = position(rng), end = position(rng);
        if (trial == 0) begin = 0, end = expected.size();
        if (begin > end) std::swap(begin, end);
        const std::span<const LinearPatch> made = patches.range(begin, end, scratch);
        REQUIRE(made.size() == end - begin);
        for (std::size_t k = 0; k < made.size(); ++k) {
          INFO("patch " << begin + k << " of the range [" << begin << ", " << end << ")");
          REQUIRE(same_bits(made[k], expected[begin + k]));
        }
      }
    }
}
