// Parts handed over differently: triangles shuffled, the whole part far from the origin.
#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

#include "ncgen/analytic_parts.hpp"
#include "ncgen/nominal_part.hpp"
#include "ncgen/placement.hpp"
#include "test_generator_checks.hpp"

using namespace ncv::gen;

namespace {

const ncv::Mesh& core() {
  static const ncv::Mesh mesh = nominal_mesh(make_mould_core(1), NominalOptions{});
  return mesh;
}

std::vector<ncv::Triangle> sorted(std::vector<ncv::Triangle> triangles) {
  std::sort(triangles.begin(), triangles.end());
  return triangles;
}

}  // namespace

TEST_CASE("shuffling permutes the triangles and nothing else", "[generator]") {
  ncv::Mesh shuffled = core();
  shuffle_triangles(shuffled, 7);
  CHECK(shuffled.vertices == core().vertices);
  CHECK(shuffled.triangles != core().triangles);
  CHECK(sorted(shuffled.triangles) == sorted(core().triangles));
  // Neighbours no longer follow each other: few triangles keep their place.
  std::size_t in_place = 0;
  for (std::size_t t = 0; t < core().triangle_count(); ++t) {
    if (shuffled.triangles[t] == core().triangles[t]) ++in_place;
  }
  CHECK(in_place < core().triangle_count() / 100);
  CHECK(test::is_sound_solid(test::check_solid(shuffled)));
}

TEST_CASE("a shuffle is fixed by its seed", "[generator]") {
  ncv::Mesh a = core();
  ncv::Mesh b = core();
  ncv::Mesh c = core();
  shuffle_triangles(a, 7);
  shuffle_triangles(b, 7);
  shuffle_triangles(c, 8);
  CHECK(a.triangles == b.triangles);
  CHECK(a.triangles != c.triangles);
}

TEST_CASE("shifting moves every vertex by exactly the vector", "[generator]") {
  const ncv::Vec3 offset(20000, -15000, 5000);
  ncv::Mesh far = core();
  shift(far, offset);
  CHECK(far.triangles == core().triangles);
  for (std::size_t v = 0; v < far.vertex_count(); ++v) {
    REQUIRE(far.vertices[v] - offset == core().vertices[v]);
    REQUIRE(far.vertices[v] == core().vertices[v] + offset);
  }
  const test::SolidReport near_report = test::check_solid(core());
  const test::SolidReport far_report = test::check_solid(far);
  CHECK(test::is_sound_solid(far_report));
  CHECK(far_report.volume == Approx(near_report.volume).epsilon(1e-9));
}

TEST_CASE("placing shuffles with its seed, then shifts", "[generator]") {
  const Placement placement{true, 3, ncv::Vec3(1, 2, 3)};
  ncv::Mesh placed = core();
  place(placed, placement);
  ncv::Mesh by_hand = core();
  shuffle_triangles(by_hand, 3);
  shift(by_hand, ncv::Vec3(1, 2, 3));
  CHECK(placed.triangles == by_hand.triangles);
  CHECK(placed.vertices == by_hand.vertices);
  ncv::Mesh unmoved = core();
  place(unmoved, Placement{});
  CHECK(unmoved.triangles == core().triangles);
  CHECK(unmoved.vertices == core().vertices);
}
