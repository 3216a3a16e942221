// The generated nominal part: a CAD-like tessellation of the mould core.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "ncgen/nominal_part.hpp"
#include "test_generator_checks.hpp"

using namespace ncv::gen;

namespace {

const ncv::Mesh& default_nominal() {
  static const ncv::Mesh mesh = nominal_mesh(make_mould_core(1), NominalOptions{});
  return mesh;
}

// Largest distance from the part's surface to a triangle's plane, over a lattice on it.
double plane_deviation(const ncv::Mesh& mesh, std::size_t t, const MouldCore& part) {
  const ncv::Vec3 a = mesh.corner(t, 0);
  const ncv::Vec3 u = mesh.corner(t, 1) - a;
  const ncv::Vec3 v = mesh.corner(t, 2) - a;
  const ncv::Vec3 normal = ncv::normalized(ncv::cross(u, v));
  double worst = 0;
  for (int i = 0; i <= 6; ++i) {
    for (int j = 0; i + j <= 6; ++j) {
      const ncv::Vec3 q = a + (i / 6.0) * u + (j / 6.0) * v;
      const ncv::Vec3 surface{q[0], q[1], part.height(q[0], q[1])};
      worst = std::max(worst, std::abs(ncv::dot(normal, surface - a)));
    }
  }
  return worst;
}

bool faces_up(const ncv::Mesh& mesh, std::size_t t) {
  return ncv::area_vector(mesh, t)[2] > 0;
}

}  // namespace

TEST_CASE("nominal core is a closed outward manifold of about 17 k triangles", "[generator]") {
  const ncv::Mesh& mesh = default_nominal();
  const test::SolidReport report = test::check_solid(mesh);
  CHECK(report.unpaired_edges == 0);
  CHECK(report.repeated_edges == 0);
  CHECK(report.non_manifold_vertices == 0);
  CHECK(report.degenerate_triangles == 0);
  CHECK(report.euler == 2);
  CHECK(report.volume > 0);
  CHECK(mesh.triangle_count() > 15'000);
  CHECK(mesh.triangle_count() < 19'000);
}

TEST_CASE("nominal core fills the 120 x 80 mm block on z = 0 up to its crown", "[generator]") {
  const ncv::BoundingBox box = ncv::bounding_box(default_nominal());
  CHECK(box.min[0] == 0);
  CHECK(box.min[1] == 0);
  CHECK(box.min[2] == 0);
  CHECK(box.max[0] == Approx(120));
  CHECK(box.max[1] == Approx(80));
  CHECK(box.max[2] > 26);  // the boss top; the crown rises above it
  CHECK(box.max[2] < 30.5);
}

TEST_CASE("nominal volume is the integral of the height field", "[generator]") {
  const MouldCore part = make_mould_core(1);
  const Grid grid = part_grid(part, 9);
  const std::vector<float> heights = sample_heights(grid, part);
  double integral = 0;  // trapezoid rule
  for (int j = 0; j <= grid.cells_y(); ++j) {
    for (int i = 0; i <= grid.cells_x(); ++i) {
      const double weight =
          (i == 0 || i == grid.cells_x() ? 0.5 : 1.0) * (j == 0 || j == grid.cells_y() ? 0.5 : 1.0);
      integral += weight * heights[grid.index(i, j)];
    }
  }
  integral *= grid.spacing * grid.spacing;
  CHECK(test::check_solid(default_nominal()).volume == Approx(integral).epsilon(1e-3));
}

TEST_CASE("nominal top vertices lie on the surface within the chord tolerance", "[generator]") {
  const MouldCore part = make_mould_core(1);
  const ncv::Mesh& mesh = default_nominal();
  for (const ncv::Vec3& v : mesh.vertices) {
    if (v[2] > 0) REQUIRE(v[2] == Approx(part.height(v[0], v[1])).margin(1e-5));
  }
  double worst = 0;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    if (faces_up(mesh, t)) worst = std::max(worst, plane_deviation(mesh, t, part));
  }
  // The RTIN measures chord errors at hypotenuse midpoints: the worst deviation anywhere
  // stays near the tolerance, not at it.
  CHECK(worst < 1.5 * NominalOptions{}.chord_tolerance);
}

TEST_CASE("nominal pocket creases are exact triangle edges", "[generator]") {
  const MouldCore part = make_mould_core(1);
  const Pocket& pocket = part.pocket;
  const ncv::Mesh& mesh = default_nominal();
  std::size_t pocket_triangles = 0;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const ncv::Vec3 c = (mesh.corner(t, 0) + mesh.corner(t, 1) + mesh.corner(t, 2)) / 3;
    if (!faces_up(mesh, t) || c[0] < pocket.min_x || c[0] > pocket.max_x || c[1] < pocket.min_y ||
        c[1] > pocket.max_y) {
      continue;
    }
    ++pocket_triangles;
    REQUIRE(plane_deviation(mesh, t, part) < 1e-9);
  }
  CHECK(pocket_triangles > 20);
}

TEST_CASE("nominal tessellates planes coarsely and curved faces finely", "[generator]") {
  const MouldCore part = make_mould_core(1);
  const ncv::Mesh& mesh = default_nominal();
  double planar_area = 0;
  double curved_area = 0;
  double planar = 0;
  double curved = 0;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    if (!faces_up(mesh, t)) continue;
    const bool on_base = mesh.corner(t, 0)[2] == part.base && mesh.corner(t, 1)[2] == part.base &&
                         mesh.corner(t, 2)[2] == part.base;
    (on_base ? planar_area : curved_area) += ncv::triangle_area(mesh, t);
    ++(on_base ? planar : curved);
  }
  REQUIRE(planar > 0);
  REQUIRE(curved > 0);
  CHECK(planar_area / planar > 10 * (curved_area / curved));
}

TEST_CASE("nominal tessellation tightens with the tolerance", "[generator]") {
  const MouldCore part = make_mould_core(1);
  const ncv::Mesh coarse = nominal_mesh(part, {9, 0.16});
  const ncv::Mesh fine = nominal_mesh(part, {9, 0.04});
  CHECK(coarse.triangle_count() < default_nominal().triangle_count());
  CHECK(fine.triangle_count() > default_nominal().triangle_count());
  CHECK(test::is_sound_solid(test::check_solid(fine)));
}

TEST_CASE("nominal core depends on the seed and only on it", "[generator]") {
  const ncv::Mesh again = nominal_mesh(make_mould_core(1), NominalOptions{});
  const ncv::Mesh other = nominal_mesh(make_mould_core(2), NominalOptions{});
  CHECK(ncv::mesh_hash(again) == ncv::mesh_hash(default_nominal()));
  CHECK(ncv::mesh_hash(other) != ncv::mesh_hash(default_nominal()));
  CHECK(test::is_sound_solid(test::check_solid(other)));
}
