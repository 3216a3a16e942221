// Lattice sampling: equation (1), lattice positions, vertex sharing, schemes I and II.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include <tbb/global_control.h>

#include "nominal_fixtures.hpp"
#include "sampling/sampling.hpp"

using namespace ncv;

namespace {

Mesh single_triangle(Vec3 a, Vec3 b, Vec3 c) {
  return Mesh{{a, b, c}, {{0, 1, 2}}};
}

// Two triangles sharing the edge 1-2: a square of side `side` in the z = 0 plane.
Mesh square(double side) {
  return Mesh{{{0, 0, 0}, {side, 0, 0}, {0, side, 0}, {side, side, 0}}, {{0, 1, 2}, {3, 2, 1}}};
}

Mesh random_mesh(std::mt19937& rng, int vertices, int triangles, double scale) {
  std::uniform_real_distribution<double> coordinate(0, scale);
  std::uniform_int_distribution<std::uint32_t> vertex(0, vertices - 1);
  Mesh mesh;
  for (int v = 0; v < vertices; ++v) {
    mesh.vertices.push_back({coordinate(rng), coordinate(rng), coordinate(rng)});
  }
  while (mesh.triangles.size() < static_cast<std::size_t>(triangles)) {
    Triangle t{vertex(rng), vertex(rng), vertex(rng)};
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) mesh.triangles.push_back(t);
  }
  return mesh;
}

}  // namespace

TEST_CASE("equation (1) gives n with n(n+1)/2 points of spacing about the step", "[sampling]") {
  // Inverting (1): n' (n' + 1) = 2|T|/step^2.
  for (double step : {0.01, 0.1, 1.0, 3.5}) {
    for (double area : {1e-6, 0.001, 0.2, 1.0, 17.0, 1000.0}) {
      const double n_prime = std::sqrt(0.25 + 2 * area / (step * step)) - 0.5;
      CHECK(n_prime * (n_prime + 1) == Approx(2 * area / (step * step)));
      CHECK(lattice_size(area, step) == static_cast<std::uint32_t>(std::lround(n_prime)));
    }
  }
  CHECK(lattice_size(0.0, 1.0) == 0);
  CHECK(lattice_size(1.0, 1.0) == 1);   // n' = 1
  CHECK(lattice_size(3.0, 1.0) == 2);   // n' = 2
  CHECK(lattice_size(6.0, 1.0) == 3);   // n' = 3
  CHECK(lattice_size(45.0, 1.0) == 9);  // n' = 9
  CHECK(lattice_point_count(6) == 21);  // the paper's Fig. 2
}

TEST_CASE("a lattice triangle has n(n+1)/2 samples at P(i,j) = A + i e1 + j e2", "[sampling]") {
  const Vec3 a{1, 2, 3}, b{7, 2, 3}, c{1, 8, 5};
  const Mesh mesh = single_triangle(a, b, c);
  const double area = 0.5 * norm(cross(b - a, c - a));
  const double step = 0.7;
  const std::uint32_t n = lattice_size(area, step);
  REQUIRE(n >= 3);
  const SampleSet set = sample_mesh(mesh, step, SamplingScheme::all);
  REQUIRE(set.sample_count() == lattice_point_count(n));
  for (std::uint32_t i = 0; i < n; ++i) {
    for (std::uint32_t j = 0; i + j < n; ++j) {
      const std::uint64_t s = set.sample_at(0, i, j);
      REQUIRE(s < set.sample_count());
      const Vec3 expected = a + (double(i) / (n - 1)) * (b - a) + (double(j) / (n - 1)) * (c - a);
      CHECK(norm(set.positions[s] - expected) < 1e-12);
      CHECK(set.lattice_i[s] == i);
      CHECK(set.lattice_j[s] == j);
    }
  }
}

TEST_CASE("sample_at is a bijection onto the samples", "[sampling]") {
  std::mt19937 rng(7);
  const Mesh mesh = random_mesh(rng, 60, 120, 10.0);
  const SampleSet set = sample_mesh(mesh, 0.4, SamplingScheme::all);
  std::vector<int> hits(set.sample_count(), 0);
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const std::uint32_t n = set.lattice_sizes[t];
    REQUIRE(n >= 2);
    for (std::uint32_t i = 0; i < n; ++i) {
      for (std::uint32_t j = 0; i + j < n; ++j) ++hits[set.sample_at(t, i, j)];
    }
  }
  // Own samples are hit once; vertex samples once per incident triangle.
  std::vector<int> valence(mesh.vertex_count(), 0);
  for (const Triangle& t : mesh.triangles) {
    for (auto v : t) ++valence[v];
  }
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    if (set.vertex_sample[v] != kNoSample) CHECK(hits[set.vertex_sample[v]] == valence[v]);
  }
  const auto vertex_samples =
      static_cast<std::size_t>(std::count_if(set.vertex_sample.begin(), set.vertex_sample.end(),
                                             [](std::uint32_t s) { return s != kNoSample; }));
  for (std::size_t s = vertex_samples; s < set.sample_count(); ++s) CHECK(hits[s] == 1);
}

TEST_CASE("mesh vertices are one sample each, computed once", "[sampling]") {
  const Mesh mesh = square(10.0);
  const SampleSet set = sample_mesh(mesh, 100.0, SamplingScheme::all);  // all tiny: n -> 2
  CHECK(set.sample_count() == 4);
  CHECK(set.lattice_sizes == std::vector<std::uint32_t>{2, 2});
  std::set<std::tuple<double, double, double>> distinct;
  for (const Vec3& p : set.positions) distinct.insert({p[0], p[1], p[2]});
  CHECK(distinct.size() == 4);
  // Both triangles' corners map to the shared vertex samples.
  CHECK(set.sample_at(0, 1, 0) == set.sample_at(1, 0, 1));  // vertex 1
  CHECK(set.sample_at(0, 0, 1) == set.sample_at(1, 1, 0));  // vertex 2
}

TEST_CASE("the (n-1)^2 sub-triangles tile every triangle", "[sampling]") {
  std::mt19937 rng(11);
  const Mesh mesh = random_mesh(rng, 40, 80, 5.0);
  for (double step : {0.05, 0.3, 2.0}) {
    const SampleSet set = sample_mesh(mesh, step, SamplingScheme::all);
    double lattice_area = 0, mesh_area = 0;
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
      mesh_area += triangle_area(mesh, t);
      const std::uint32_t n = set.lattice_sizes[t];
      auto p = [&](std::uint32_t i, std::uint32_t j) {
        return set.positions[set.sample_at(t, i, j)];
      };
      for (std::uint32_t i = 0; i + 1 < n; ++i) {
        for (std::uint32_t j = 0; i + j + 1 < n; ++j) {
          lattice_area += 0.5 * norm(cross(p(i + 1, j) - p(i, j), p(i, j + 1) - p(i, j)));
          if (i + j + 2 < n) {
            lattice_area +=
                0.5 * norm(cross(p(i, j + 1) - p(i + 1, j), p(i + 1, j + 1) - p(i + 1, j)));
          }
        }
      }
    }
    CHECK(lattice_area == Approx(mesh_area).epsilon(1e-10));
  }
}

TEST_CASE("scheme II skips exactly the triangles with n < 2", "[sampling]") {
  // A large triangle (n >= 2) and a tiny one far away.
  Mesh mesh{{{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {50, 50, 50}, {50.01, 50, 50}, {50, 50.01, 50}},
            {{0, 1, 2}, {3, 4, 5}}};
  const double step = 1.0;
  REQUIRE(lattice_size(triangle_area(mesh, 0), step) >= 2);
  REQUIRE(lattice_size(triangle_area(mesh, 1), step) < 2);
  SamplingReport report_i, report_ii;
  const SampleSet all = sample_mesh(mesh, step, SamplingScheme::all, &report_i);
  const SampleSet skip = sample_mesh(mesh, step, SamplingScheme::paper_ii, &report_ii);
  CHECK(all.lattice_sizes[1] == 2);
  CHECK(skip.lattice_sizes[1] == 0);
  CHECK(all.sample_count() == skip.sample_count() + 3);
  CHECK(skip.vertex_sample[3] == kNoSample);
  CHECK(report_i.small_triangles == 1);
  CHECK(report_ii.small_triangles == 1);
  CHECK(predicted_sample_count(mesh, plan_sampling(mesh, step, SamplingScheme::all)) ==
        all.sample_count());
  CHECK(predicted_sample_count(mesh, plan_sampling(mesh, step, SamplingScheme::paper_ii)) ==
        skip.sample_count());
}

TEST_CASE("degenerate triangles are counted and sampled at their vertices", "[sampling]") {
  Mesh mesh{{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 1, 3}}};
  SamplingReport report;
  const SampleSet set = sample_mesh(mesh, 0.1, SamplingScheme::all, &report);
  CHECK(report.degenerate_triangles == 1);
  CHECK(set.lattice_sizes[0] == 2);
  CHECK(set.vertex_sample[2] != kNoSample);
}

TEST_CASE("a vertex sample belongs to the lowest-index sampled triangle, on any thread count",
          "[sampling]") {
  // Some 29 k triangles of many sizes (a torus with shuffled triangles, then every third
  // one shrunk towards its first corner), so that ownership is decided across blocks and
  // scheme II leaves some triangles out.
  Mesh mesh = fixtures::torus(40, 10, 240, 60);
  std::mt19937_64 rng(5);
  std::shuffle(mesh.triangles.begin(), mesh.triangles.end(), rng);
  for (std::size_t t = 0; t < mesh.triangle_count(); t += 3) {
    const std::uint32_t a = mesh.triangles[t][0];
    for (int k = 1; k < 3; ++k) {
      Vec3& corner = mesh.vertices[mesh.triangles[t][k]];
      corner = mesh.vertices[a] + 0.999 * (corner - mesh.vertices[a]);
    }
  }
  const double step = 0.6;
  const auto sample = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                              static_cast<std::size_t>(threads));
    return sample_mesh(mesh, step, SamplingScheme::paper_ii);
  };
  const SampleSet one = sample(1);
  const SampleSet two = sample(2);
  REQUIRE(one.vertex_sample == two.vertex_sample);
  REQUIRE(one.owner == two.owner);
  REQUIRE(one.lattice_i == two.lattice_i);
  REQUIRE(one.lattice_j == two.lattice_j);
  REQUIRE(std::count(one.lattice_sizes.begin(), one.lattice_sizes.end(), 0u) > 0);

  std::vector<std::uint32_t> lowest(mesh.vertex_count(), kNoSample);
  for (std::size_t t = mesh.triangle_count(); t-- > 0;) {
    if (one.lattice_sizes[t] == 0) continue;
    for (const std::uint32_t v : mesh.triangles[t]) lowest[v] = static_cast<std::uint32_t>(t);
  }
  for (std::uint32_t v = 0; v < mesh.vertex_count(); ++v) {
    INFO("vertex " << v);
    REQUIRE((one.vertex_sample[v] == kNoSample) == (lowest[v] == kNoSample));
    if (lowest[v] == kNoSample) continue;
    const std::uint32_t s = one.vertex_sample[v];
    REQUIRE(one.owner[s] == lowest[v]);
    REQUIRE(one.sample_at(lowest[v], one.lattice_i[s], one.lattice_j[s]) == s);
  }
  CHECK(predicted_sample_count(mesh, plan_sampling(mesh, step, SamplingScheme::paper_ii)) ==
        one.sample_count());
}
