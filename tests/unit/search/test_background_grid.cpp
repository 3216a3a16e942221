// The background grid: the exact triangle-box test against a clipping oracle, complete and
// ascending cell lists, the memory bounds on hostile meshes, the thread-count invariance
// of the build, and the validation of grids read from untrusted files.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include <tbb/global_control.h>

#include "geometry/triangle_box_overlap.hpp"
#include "nominal_fixtures.hpp"
#include "search/coarse_grid.hpp"
#include "search/grid_builder.hpp"
#include "util/error.hpp"

namespace {

using ncv::Vec3;
namespace fx = ncv::fixtures;

// Sutherland-Hodgman: clip the triangle by the six (closed) half-spaces of the box; they
// meet when anything is left.
bool clipping_overlap(Vec3 centre, Vec3 half, Vec3 a, Vec3 b, Vec3 c) {
  std::vector<Vec3> polygon{a, b, c};
  for (int axis = 0; axis < 3; ++axis) {
    for (double side : {-1.0, 1.0}) {
      const double limit = centre[axis] + side * half[axis];
      const auto inside = [&](Vec3 p) { return side * (p[axis] - limit) <= 0; };
      std::vector<Vec3> clipped;
      for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Vec3 p = polygon[i];
        const Vec3 q = polygon[(i + 1) % polygon.size()];
        if (inside(p)) clipped.push_back(p);
        if (inside(p) != inside(q)) {
          const double t = (limit - p[axis]) / (q[axis] - p[axis]);
          Vec3 crossing = p + t * (q - p);
          crossing[axis] = limit;
          clipped.push_back(crossing);
        }
      }
      polygon = std::move(clipped);
      if (polygon.empty()) return false;
    }
  }
  return true;
}

ncv::ReferenceSurface nominal_of(ncv::Mesh mesh) {
  return ncv::ReferenceSurface(std::move(mesh), "test");
}

// Every cell the triangle touches (exact test on the cell's own bounds) lists it, every
// list is strictly ascending, and nothing is listed in a cell it does not come near.
void check_lists_complete(const ncv::ReferenceSurface& nominal, const ncv::BackgroundGrid& grid) {
  const double h = grid.cell_size;
  const Vec3 half{0.5 * h, 0.5 * h, 0.5 * h};
  const Vec3 grown{0.5 * h * (1 + 1e-6), 0.5 * h * (1 + 1e-6), 0.5 * h * (1 + 1e-6)};
  for (std::uint32_t k = 0; k < grid.dims[2]; ++k) {
    for (std::uint32_t j = 0; j < grid.dims[1]; ++j) {
      for (std::uint32_t i = 0; i < grid.dims[0]; ++i) {
        const std::uint64_t cell = grid.cell_index(i, j, k);
        const Vec3 lo{grid.cell_bound(0, i), grid.cell_bound(1, j), grid.cell_bound(2, k)};
        const Vec3 centre = lo + half;
        const auto first =
            grid.cell_triangles.begin() + static_cast<std::ptrdiff_t>(grid.cell_offsets[cell]);
        const auto last =
            grid.cell_triangles.begin() + static_cast<std::ptrdiff_t>(grid.cell_offsets[cell + 1]);
        REQUIRE(std::adjacent_find(first, last, std::greater_equal<>()) == last);
        for (std::uint32_t t = 0; t < nominal.triangle_count(); ++t) {
          const auto& [a, b, c] = nominal.corners(t);
          const bool listed = std::binary_search(first, last, t);
          if (ncv::triangle_box_overlap(centre, half, a, b, c)) REQUIRE(listed);
          if (listed) REQUIRE(ncv::triangle_box_overlap(centre, grown, a, b, c));
        }
      }
    }
  }
}

}  // namespace

TEST_CASE("triangle-box overlap agrees with clipping on random cases", "[grid]") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> size(0.05, 1.0);
  int overlaps = 0;
  const int cases = 50000;
  for (int i = 0; i < cases; ++i) {
    const Vec3 centre{unit(rng), unit(rng), unit(rng)};
    const Vec3 half{size(rng), size(rng), size(rng)};
    const double scale = i % 3 == 0 ? 0.3 : 2.0;  // small triangles and large ones
    const Vec3 a{unit(rng), unit(rng), unit(rng)};
    const Vec3 b = a + scale * Vec3{unit(rng), unit(rng), unit(rng)};
    const Vec3 c = a + scale * Vec3{unit(rng), unit(rng), unit(rng)};
    const bool expected = clipping_overlap(centre, half, a, b, c);
    REQUIRE(ncv::triangle_box_overlap(centre, half, a, b, c) == expected);
    overlaps += expected;
  }
  // Both outcomes well represented.
  CHECK(overlaps > cases / 5);
  CHECK(overlaps < cases * 4 / 5);
}

// The separating-axis test as Akenine-Möller writes it, each edge axis the full cross
// product of a box axis and an edge (the form the grid's slack was argued for): the grid's
// cells must be the ones it gives, bit for bit. Without the edge axes (edge_axes false) it
// is the face and plane tests alone.
bool full_cross_sat(Vec3 centre, Vec3 half, Vec3 a, Vec3 b, Vec3 c, bool edge_axes = true) {
  const Vec3 v0 = a - centre, v1 = b - centre, v2 = c - centre;
  for (int axis = 0; axis < 3; ++axis) {
    if (std::min({v0[axis], v1[axis], v2[axis]}) > half[axis] ||
        std::max({v0[axis], v1[axis], v2[axis]}) < -half[axis]) {
      return false;
    }
  }
  const auto radius = [&](Vec3 axis) {
    return half[0] * std::fabs(axis[0]) + half[1] * std::fabs(axis[1]) +
           half[2] * std::fabs(axis[2]);
  };
  const Vec3 normal = ncv::cross(v1 - v0, v2 - v0);
  if (std::fabs(ncv::dot(normal, v0)) > radius(normal)) return false;
  if (!edge_axes) return true;
  const Vec3 edges[3] = {v1 - v0, v2 - v1, v0 - v2};
  for (const Vec3& e : edges) {
    for (int k = 0; k < 3; ++k) {
      Vec3 box_axis{0, 0, 0};
      box_axis[k] = 1;
      const Vec3 axis = ncv::cross(box_axis, e);
      const double p0 = ncv::dot(axis, v0), p1 = ncv::dot(axis, v1), p2 = ncv::dot(axis, v2);
      if (std::min({p0, p1, p2}) > radius(axis) || std::max({p0, p1, p2}) < -radius(axis)) {
        return false;
      }
    }
  }
  return true;
}

TEST_CASE("triangle-box overlap is the full separating-axis test to the last bit", "[grid]") {
  // Triangles whose edge-axis projections land within rounding of the box's radius: an edge
  // through a point a few ulps either side of a box corner, at every scale, some edges in a
  // coordinate plane or along an axis (zero components, whose products the fast form leaves
  // out).
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> ulps(-4, 4), exponent(-30, 30), pick(0, 5);
  int agreed_overlaps = 0, edge_decided = 0;
  const int cases = 200000;
  for (int i = 0; i < cases; ++i) {
    const double scale = std::ldexp(1.0, exponent(rng));
    const Vec3 half =
        scale * Vec3{0.5 + 0.5 * std::fabs(unit(rng)), 0.5 + 0.5 * std::fabs(unit(rng)),
                     0.5 + 0.5 * std::fabs(unit(rng))};
    const Vec3 centre = scale * Vec3{unit(rng), unit(rng), unit(rng)};
    // A box corner, nudged by a few ulps, that the triangle's edge passes by.
    Vec3 corner = centre + Vec3{half[0], -half[1], half[2]};
    for (int k = 0; k < 3; ++k) {
      for (int u = ulps(rng); u != 0; u += u > 0 ? -1 : 1) {
        corner[k] = std::nextafter(corner[k], u > 0 ? INFINITY : -INFINITY);
      }
    }
    Vec3 direction{unit(rng), unit(rng), unit(rng)};
    if (pick(rng) == 0) direction[pick(rng) % 3] = 0;  // an edge in a coordinate plane
    if (pick(rng) == 0) {                              // along an axis
      direction = Vec3{0, 0, 0};
      direction[pick(rng) % 3] = 1;
    }
    const Vec3 a = corner - scale * direction;
    const Vec3 b = corner + scale * direction;
    const Vec3 c = a + scale * Vec3{unit(rng), unit(rng), unit(rng)};
    const bool expected = full_cross_sat(centre, half, a, b, c);
    REQUIRE(ncv::triangle_box_overlap(centre, half, a, b, c) == expected);
    agreed_overlaps += expected;
    // Separated by an edge axis alone: the face axes and the plane do not separate them.
    edge_decided += !expected && full_cross_sat(centre, half, a, b, c, false);
  }
  CHECK(agreed_overlaps > cases / 10);
  CHECK(agreed_overlaps < cases * 9 / 10);
  CHECK(edge_decided > 0);
}

TEST_CASE("triangle-box overlap on touching and edge-separated cases", "[grid]") {
  const Vec3 centre{0, 0, 0}, half{1, 1, 1};
  const auto overlap = [&](Vec3 a, Vec3 b, Vec3 c) {
    return ncv::triangle_box_overlap(centre, half, a, b, c);
  };
  CHECK(overlap({-0.5, -0.5, 1}, {0.5, -0.5, 1}, {0, 0.5, 1}));  // lies on the top face
  CHECK_FALSE(overlap({-0.5, -0.5, 1 + 1e-12}, {0.5, -0.5, 1 + 1e-12}, {0, 0.5, 1 + 1e-12}));
  CHECK(overlap({1, 1, 1}, {3, 1, 1}, {1, 3, 2}));     // only a corner in common
  CHECK(overlap({-5, -5, 0}, {5, -5, 0}, {0, 5, 0}));  // slices through, corners all outside
  // Plane and box axes overlap; only the edge x y-axis separates.
  CHECK_FALSE(overlap({2.6, 0, 0}, {0, 0, 2.6}, {3, 0, 3}));
  CHECK(overlap({1.9, 0, 0}, {0, 0, 1.9}, {3, 0, 3}));
  // Degenerate triangles: a segment through the box, a segment beside it, a point inside.
  CHECK(overlap({-3, 0.5, 0.5}, {3, 0.5, 0.5}, {0, 0.5, 0.5}));
  CHECK(overlap({1.5, 0, -3}, {-1.5, 0, 3}, {0, 0, 0}));
  CHECK_FALSE(overlap({2.1, 0, 0}, {0, 0, 2.1}, {1.05, 0, 1.05}));
  CHECK(overlap({0.1, 0.2, 0.3}, {0.1, 0.2, 0.3}, {0.1, 0.2, 0.3}));
}

// The equilateral triangle of edge 1 in the plane z = 0, cut into n^2 equilateral triangles
// of edge 1/n.
ncv::Mesh subdivided_equilateral(std::uint32_t n) {
  ncv::Mesh mesh;
  const auto index = [n](std::uint32_t i, std::uint32_t j) {
    return i * (n + 1) - i * (i - 1) / 2 + j;  // row i holds n + 1 - i points
  };
  for (std::uint32_t i = 0; i <= n; ++i) {
    for (std::uint32_t j = 0; i + j <= n; ++j) {
      mesh.vertices.push_back({(j + 0.5 * i) / n, i * std::sqrt(3.0) / 2 / n, 0});
    }
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    for (std::uint32_t j = 0; i + j < n; ++j) {
      mesh.triangles.push_back({index(i, j), index(i, j + 1), index(i + 1, j)});
      if (i + j + 1 < n) {
        mesh.triangles.push_back({index(i, j + 1), index(i + 1, j + 1), index(i + 1, j)});
      }
    }
  }
  return mesh;
}

TEST_CASE("default cell size is the paper's equilateral edge", "[grid]") {
  // 65536 triangles of edge 1/256: the part's box (1 by sqrt(3)/2, flat) holds far more
  // than the least default count of such cells, so the paper's edge stands.
  CHECK(ncv::default_cell_size(nominal_of(subdivided_equilateral(256))) ==
        Approx(1.0 / 256).epsilon(1e-9));
}

// The grid on a nominal of a few large triangles: the default cell is finer than the
// paper's (`paper`), the grid has at most kLeastDefaultCells cells, and a cell 1 % finer
// would give more.
void check_least_cells(const ncv::Mesh& mesh, double paper) {
  const auto nominal = nominal_of(mesh);
  const double h = ncv::default_cell_size(nominal);
  CHECK(h < paper);
  ncv::GridStatistics stats;
  const ncv::BackgroundGrid grid = ncv::build_background_grid(nominal, {}, &stats);
  CHECK(stats.growth_steps == 0);
  CHECK(grid.cell_size == h);
  CHECK(grid.cell_count() <= ncv::kLeastDefaultCells);
  check_lists_complete(nominal, grid);
  ncv::GridOptions finer;
  finer.cell_size = 0.99 * h;
  CHECK(ncv::build_background_grid(nominal, finer).cell_count() > ncv::kLeastDefaultCells);
}

TEST_CASE("default cells of a few large triangles number at least the least default", "[grid]") {
  SECTION("a solid's box") {
    // A regular tetrahedron of edge 2 (the paper's cell: 2).
    ncv::Mesh tetra;
    tetra.vertices = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    for (Vec3& v : tetra.vertices) v = v * (1 / std::sqrt(2.0));
    tetra.triangles = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
    check_least_cells(tetra, 2.0);
    check_least_cells(fx::box({0, 0, 0}, {40, 20, 10}), 23.2);  // mean area 2800 / 12
  }
  SECTION("a flat part's box counts one layer") {
    check_least_cells(subdivided_equilateral(2), 0.5);
  }
  SECTION("a straight part's box counts one row") {
    // Zero area: the paper's cell is the box's diagonal, 3.
    ncv::Mesh sliver;
    sliver.vertices = {{0, 0, 0}, {3, 0, 0}, {1, 0, 0}};
    sliver.triangles = {{0, 1, 2}};
    check_least_cells(sliver, 3.0);
  }
}

TEST_CASE("grid lists every triangle in every cell it touches", "[grid]") {
  std::mt19937_64 rng(5);
  SECTION("random soup") {
    const auto nominal = nominal_of(fx::random_soup(rng, 300, 0.2));
    const ncv::BackgroundGrid grid = ncv::build_background_grid(nominal);
    grid.validate(nominal, "built");
    check_lists_complete(nominal, grid);
  }
  SECTION("axis-aligned faces on cell boundaries") {
    // Unit cells on a lattice solid: many faces lie exactly on cell planes.
    const auto nominal = nominal_of(fx::pocketed_block().mesh(1.0));
    ncv::GridOptions options;
    options.cell_size = 0.5;
    ncv::GridStatistics stats;
    const ncv::BackgroundGrid grid = ncv::build_background_grid(nominal, options, &stats);
    CHECK(stats.growth_steps == 0);
    CHECK(grid.cell_size == 0.5);
    check_lists_complete(nominal, grid);
  }
  SECTION("degenerate triangles") {
    ncv::Mesh mesh = fx::box({0, 0, 0}, {1, 1, 1});
    mesh.vertices.push_back({0.2, 0.3, 0.4});
    mesh.vertices.push_back({0.8, 0.6, 0.4});
    mesh.vertices.push_back({0.5, 0.45, 0.4});  // collinear with the two above
    mesh.triangles.push_back({8, 9, 10});
    mesh.triangles.push_back({8, 8, 8});
    const auto nominal = nominal_of(std::move(mesh));
    ncv::GridOptions options;
    options.cell_size = 0.1;
    check_lists_complete(nominal, ncv::build_background_grid(nominal, options));
  }
}

TEST_CASE("the coarse level lists every triangle in every cell it touches", "[grid]") {
  std::mt19937_64 rng(9);
  const auto nominal = nominal_of(fx::random_soup(rng, 300, 0.2));
  for (const double h : {0.05, 0.07, 0.13}) {  // odd and even fine dimensions
    CAPTURE(h);
    ncv::GridOptions options;
    options.cell_size = h;
    const ncv::BackgroundGrid fine = ncv::build_background_grid(nominal, options);
    const ncv::BackgroundGrid coarse = ncv::coarsen(fine);
    CHECK(coarse.cell_size == 2 * fine.cell_size);
    for (int axis = 0; axis < 3; ++axis) {
      CHECK(coarse.dims[axis] == (fine.dims[axis] + 1) / 2);
      // Every coarse bound is a fine one, to the bit.
      for (std::int64_t i = 0; i <= coarse.dims[axis]; ++i) {
        REQUIRE(coarse.cell_bound(axis, i) == fine.cell_bound(axis, 2 * i));
      }
    }
    coarse.validate(nominal, "coarse");
    check_lists_complete(nominal, coarse);
  }
}

TEST_CASE("grid statistics describe the grid", "[grid]") {
  const auto nominal = nominal_of(fx::torus(2, 0.5, 40, 20));
  ncv::GridStatistics stats;
  const ncv::BackgroundGrid grid = ncv::build_background_grid(nominal, {}, &stats);
  CHECK(stats.dims == grid.dims);
  CHECK(stats.cells == grid.cell_count());
  CHECK(stats.references == grid.cell_triangles.size());
  CHECK(stats.references_per_triangle == Approx(static_cast<double>(stats.references) /
                                                static_cast<double>(nominal.triangle_count())));
  CHECK(stats.bytes == grid.cell_offsets.size() * 4 + grid.cell_triangles.size() * 4);
  CHECK(stats.cell_size == grid.cell_size);
  CHECK(stats.requested_cell_size == ncv::default_cell_size(nominal));
  std::uint64_t empty = 0, largest = 0;
  for (std::uint64_t c = 0; c < grid.cell_count(); ++c) {
    const std::uint64_t size = grid.cell_offsets[c + 1] - grid.cell_offsets[c];
    empty += size == 0;
    largest = std::max(largest, size);
  }
  CHECK(stats.empty_cells == empty);
  CHECK(stats.max_cell_triangles == largest);
  CHECK(empty > 0);
  // The grid box holds the part with room to spare.
  const ncv::BoundingBox box = grid.bounds();
  for (int axis = 0; axis < 3; ++axis) {
    CHECK(box.min[axis] < nominal.local_bounds().min[axis]);
    CHECK(box.max[axis] > nominal.local_bounds().max[axis]);
  }
}

TEST_CASE("grid memory stays bounded for huge triangles among tiny ones", "[grid]") {
  std::mt19937_64 rng(3);
  SECTION("2 huge + 100k tiny triangles") {
    ncv::Mesh mesh = fx::translated(fx::random_soup(rng, 100000, 0.01), {0, 0, 0});
    for (Vec3& v : mesh.vertices) v = v * 1000.0;
    const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
    mesh.vertices.insert(
        mesh.vertices.end(),
        {{0, 0, 0}, {1000, 0, 0}, {0, 1000, 0}, {1000, 1000, 1000}, {1000, 0, 500}});
    mesh.triangles.push_back({base, base + 1, base + 2});
    mesh.triangles.push_back({base, base + 3, base + 4});
    const auto nominal = nominal_of(std::move(mesh));
    ncv::GridStatistics stats;
    const ncv::BackgroundGrid grid = ncv::build_background_grid(nominal, {}, &stats);
    const std::uint64_t t = nominal.triangle_count();
    CHECK(stats.cells <= ncv::kCellsPerTriangle * t);
    CHECK(stats.references <= ncv::kReferencesPerTriangle * t);
    CHECK(stats.growth_steps > 0);
    CHECK(stats.cell_size > stats.requested_cell_size);
    grid.validate(nominal, "built");
  }
  SECTION("a stack of large parallel squares hits the reference bound") {
    ncv::Mesh mesh;
    for (std::uint32_t layer = 0; layer < 200; ++layer) {
      const double z = layer * 0.005;
      const std::uint32_t v = layer * 4;
      mesh.vertices.insert(mesh.vertices.end(), {{0, 0, z}, {1, 0, z}, {1, 1, z}, {0, 1, z}});
      mesh.triangles.push_back({v, v + 1, v + 2});
      mesh.triangles.push_back({v, v + 2, v + 3});
    }
    const auto nominal = nominal_of(std::move(mesh));
    ncv::GridOptions options;
    options.cell_size = 1e-4;  // absurdly small: both bounds must step in
    ncv::GridStatistics stats;
    const ncv::BackgroundGrid grid = ncv::build_background_grid(nominal, options, &stats);
    CHECK(stats.cells <= ncv::kMinCellBudget);
    CHECK(stats.references <= ncv::kMinReferenceBudget);
    CHECK(stats.references > ncv::kMinReferenceBudget / 4);  // not grown far beyond need
    check_lists_complete(nominal, grid);
  }
}

TEST_CASE("grid build does not depend on the thread count", "[grid]") {
  std::mt19937_64 rng(9);
  const auto nominal = nominal_of(fx::random_soup(rng, 5000, 0.1));
  const auto build_with = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return ncv::build_background_grid(nominal);
  };
  const ncv::BackgroundGrid one = build_with(1);
  const ncv::BackgroundGrid two = build_with(2);
  CHECK(one.origin == two.origin);
  CHECK(one.cell_size == two.cell_size);
  CHECK(one.dims == two.dims);
  CHECK(one.cell_offsets == two.cell_offsets);
  CHECK(one.cell_triangles == two.cell_triangles);
}

TEST_CASE("a cell size far below the part's size grows without overflow", "[grid]") {
  const ncv::ReferenceSurface nominal(fx::box({0, 0, 0}, {1e90, 1e90, 1e90}), "huge");
  for (double tiny : {1e-300, 5e-324, 1.0}) {
    ncv::GridOptions options;
    options.cell_size = tiny;
    ncv::GridStatistics stats;
    const ncv::BackgroundGrid grid = ncv::build_background_grid(nominal, options, &stats);
    CHECK(stats.cells <= ncv::kMinCellBudget);
    CHECK(std::isfinite(grid.cell_size));
    grid.validate(nominal, "built");
  }
}

TEST_CASE("grid options are checked", "[grid]") {
  const auto nominal = nominal_of(fx::box({0, 0, 0}, {1, 1, 1}));
  for (double bad : {-1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    ncv::GridOptions options;
    options.cell_size = bad;
    CHECK_THROWS_AS(ncv::build_background_grid(nominal, options), ncv::UsageError);
  }
}

TEST_CASE("grid validation rejects every kind of corruption", "[grid]") {
  std::mt19937_64 rng(2);
  const auto nominal = nominal_of(fx::random_soup(rng, 200, 0.2));
  const ncv::BackgroundGrid good = ncv::build_background_grid(nominal);
  REQUIRE_NOTHROW(good.validate(nominal, "grid.bin"));
  REQUIRE(good.cell_triangles.size() > 2);

  const auto rejects = [&](auto&& corrupt, const char* what) {
    ncv::BackgroundGrid grid = good;
    corrupt(grid);
    INFO(what);
    CHECK_THROWS_AS(grid.validate(nominal, "grid.bin"), ncv::InputError);
    try {
      grid.validate(nominal, "grid.bin");
    } catch (const ncv::InputError& e) {
      CHECK(std::string(e.what()).rfind("grid.bin: ", 0) == 0);
    }
  };
  rejects([](ncv::BackgroundGrid& g) { g.cell_size = 0; }, "zero cell size");
  rejects([](ncv::BackgroundGrid& g) { g.cell_size = std::nan(""); }, "NaN cell size");
  rejects([](ncv::BackgroundGrid& g) { g.cell_size = 1e308; }, "grid beyond double range");
  rejects([](ncv::BackgroundGrid& g) { g.origin[1] = std::numeric_limits<double>::infinity(); },
          "infinite origin");
  rejects([](ncv::BackgroundGrid& g) { g.dims[1] = 0; }, "zero dimension");
  rejects(
      [](ncv::BackgroundGrid& g) {
        g.dims = {4000000000u, 4000000000u, 4000000000u};
      },
      "dimension product overflows");
  rejects([](ncv::BackgroundGrid& g) { ++g.dims[0]; }, "dims do not match offsets");
  rejects([](ncv::BackgroundGrid& g) { g.cell_offsets.pop_back(); }, "offsets too short");
  rejects([](ncv::BackgroundGrid& g) { g.cell_offsets.clear(); }, "no offsets");
  rejects([](ncv::BackgroundGrid& g) { g.cell_offsets[0] = 1; }, "offsets not from zero");
  rejects([](ncv::BackgroundGrid& g) { g.cell_triangles.pop_back(); }, "offsets past the lists");
  rejects(
      [](ncv::BackgroundGrid& g) {
        const auto c = std::find_if(g.cell_offsets.begin() + 1, g.cell_offsets.end(),
                                    [](std::uint64_t o) { return o > 0; });
        *(c - 1) = *c + 1;
      },
      "decreasing offsets");
  rejects([&](ncv::BackgroundGrid& g) { g.cell_triangles[0] = 200; }, "triangle out of range");
  rejects(
      [](ncv::BackgroundGrid& g) {
        for (std::size_t c = 0; c + 1 < g.cell_offsets.size(); ++c) {
          if (g.cell_offsets[c + 1] - g.cell_offsets[c] >= 2) {
            std::swap(g.cell_triangles[g.cell_offsets[c]], g.cell_triangles[g.cell_offsets[c] + 1]);
            return;
          }
        }
      },
      "unsorted list");
  rejects([](ncv::BackgroundGrid& g) { g.origin[0] += 0.5; }, "does not cover the nominal");
  rejects(
      [](ncv::BackgroundGrid& g) {
        // Drop triangle 0 from every list it is in.
        ncv::BackgroundGrid pruned = g;
        pruned.cell_triangles.clear();
        for (std::size_t c = 0; c + 1 < g.cell_offsets.size(); ++c) {
          pruned.cell_offsets[c] = static_cast<std::uint32_t>(pruned.cell_triangles.size());
          for (std::uint64_t r = g.cell_offsets[c]; r < g.cell_offsets[c + 1]; ++r) {
            if (g.cell_triangles[r] != 0) pruned.cell_triangles.push_back(g.cell_triangles[r]);
          }
        }
        pruned.cell_offsets.back() = static_cast<std::uint32_t>(pruned.cell_triangles.size());
        g = pruned;
      },
      "a triangle in no cell");
  CHECK_THROWS_AS(good.validate(199, "grid.bin"), ncv::InputError);
}

TEST_CASE("the cells meeting an interval are those whose closed extent meets it", "[grid]") {
  // An origin and a cell size whose bounds round (0.1 is not a binary fraction), intervals
  // ending on cell faces, within rounding of them, inside one cell, and beyond the grid.
  ncv::BackgroundGrid grid;
  grid.origin = Vec3(-3.7, 0.1, 1e3);
  grid.cell_size = 0.1;
  grid.dims = {37, 5, 1};
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> face(-3, 40);
  std::uniform_real_distribution<double> u(-0.5, 4.5);
  for (int trial = 0; trial < 20000; ++trial) {
    const int axis = trial % 3;
    const std::int64_t end = grid.dims[axis];
    double low = 0, high = 0;
    switch (trial % 4) {
      case 0:  // on faces
        low = grid.cell_bound(axis, face(rng));
        high = grid.cell_bound(axis, face(rng));
        break;
      case 1:  // a step off faces
        low = std::nextafter(grid.cell_bound(axis, face(rng)), trial % 8 < 4 ? -1e9 : 1e9);
        high = std::nextafter(grid.cell_bound(axis, face(rng)), trial % 8 < 4 ? 1e9 : -1e9);
        break;
      default:
        low = grid.origin[axis] + u(rng) * static_cast<double>(end) * grid.cell_size / 4;
        high = low + std::fabs(u(rng)) * grid.cell_size;
    }
    if (low > high) std::swap(low, high);
    // The last cell starting at or below low, the first ending at or above high.
    std::int64_t want_first = 0, want_last = end - 1;
    for (std::int64_t i = 0; i < end; ++i) {
      if (grid.cell_bound(axis, i) <= low) want_first = i;
    }
    for (std::int64_t i = end - 1; i >= 0; --i) {
      if (grid.cell_bound(axis, i + 1) >= high) want_last = i;
    }
    want_last = std::max(want_last, want_first);
    const bool on_grid = low <= grid.cell_bound(axis, end) && high >= grid.cell_bound(axis, 0);
    std::int64_t first = -1, last = -1;
    REQUIRE(grid.cells_meeting(axis, low, high, first, last) == on_grid);
    if (!on_grid) continue;
    CHECK(first == want_first);
    CHECK(last == want_last);
    // They hold the interval, each of them meets it.
    CHECK(grid.cell_bound(axis, first) <= std::max(low, grid.cell_bound(axis, 0)));
    CHECK(grid.cell_bound(axis, last + 1) >= std::min(high, grid.cell_bound(axis, end)));
  }
}
