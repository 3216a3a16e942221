// The nominal prepared for queries: local frame, input checks, orientation, normals and
// pseudonormals, and the automatic choice of sign method.
#include <cmath>

#include <catch2/catch.hpp>

#include <tbb/global_control.h>

#include "nominal_fixtures.hpp"
#include "reference/reference_surface.hpp"
#include "util/error.hpp"

namespace {

using ncv::Vec3;
namespace fx = ncv::fixtures;

bool near(Vec3 a, Vec3 b, double tolerance = 1e-12) {
  return ncv::norm(a - b) <= tolerance;
}

}  // namespace

TEST_CASE("nominal: local frame at the bounding-box centre", "[nominal]") {
  const ncv::Mesh mesh = fx::box({1e6, 2, 3}, {1e6 + 4, 6, 5});
  const ncv::ReferenceSurface nominal(mesh, "part.stl");
  CHECK(nominal.origin() == Vec3{1e6 + 2, 4, 4});
  CHECK(nominal.local_bounds().min == Vec3{-2, -2, -1});
  CHECK(nominal.local_bounds().max == Vec3{2, 2, 1});
  CHECK(nominal.to_local({1e6 + 1, 2.5, 3.5}) == Vec3{-1, -1.5, -0.5});
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    for (int k = 0; k < 3; ++k) {
      CHECK(nominal.corners(t)[k] == mesh.corner(t, k) - nominal.origin());
    }
  }
}

TEST_CASE("nominal: unusable meshes are refused with the file name", "[nominal]") {
  const auto refuses = [](ncv::Mesh mesh, const char* fragment) {
    try {
      ncv::ReferenceSurface nominal(std::move(mesh), "cad.stl");
      FAIL("accepted a mesh that " << fragment);
    } catch (const ncv::InputError& e) {
      const std::string message = e.what();
      CHECK(message.rfind("cad.stl: ", 0) == 0);
      CHECK(message.find(fragment) != std::string::npos);
    }
  };
  refuses(ncv::Mesh{}, "no triangles");
  ncv::Mesh mesh = fx::box({0, 0, 0}, {1, 1, 1});
  mesh.triangles[3][1] = 8;
  refuses(mesh, "refers to vertex 8");
  mesh = fx::box({0, 0, 0}, {1, 1, 1});
  mesh.vertices[2][1] = std::nan("");
  refuses(mesh, "not finite");
  mesh = fx::box({0, 0, 0}, {1, 1, 1});
  mesh.vertices[5][2] = -1e101;
  refuses(mesh, "beyond");
}

TEST_CASE("nominal: face normals and pseudonormals of a box", "[nominal]") {
  // Faces split into several triangles of different corner angles: the angle weighting
  // must still give the symmetric corner normal.
  fx::VoxelSolid cube;
  cube.fill(0, 0, 0, 2, 2, 2);
  const ncv::ReferenceSurface nominal(cube.mesh(1.0), "box");
  const Vec3 diagonal = ncv::normalized({1, 1, 1});
  for (std::size_t t = 0; t < nominal.triangle_count(); ++t) {
    const ncv::TriangleCorners& corners = nominal.corners(t);
    const Vec3 n = nominal.face_normal(t);
    CHECK(ncv::norm(n) == Approx(1.0));
    // Outward: the face centre moved along n leaves the box centred at the local origin.
    const Vec3 centre = (corners[0] + corners[1] + corners[2]) / 3.0;
    CHECK(ncv::dot(n, centre) > 0);
    CHECK(near(nominal.pseudonormal(t, ncv::TriangleFeature::face), n));
    for (int k = 0; k < 3; ++k) {
      const Vec3 corner = corners[k];
      const Vec3 vertex_normal = nominal.pseudonormal(t, ncv::vertex_feature(k));
      const bool box_corner =
          std::fabs(corner[0]) == 1 && std::fabs(corner[1]) == 1 && std::fabs(corner[2]) == 1;
      if (box_corner) {
        CHECK(near(vertex_normal, Vec3{corner[0] * diagonal[0], corner[1] * diagonal[1],
                                       corner[2] * diagonal[2]}));
      }
      // An edge between two faces of one side has that side's normal; a box edge, the
      // bisector of its two sides.
      const Vec3 mid = 0.5 * (corner + corners[(k + 1) % 3]);
      const Vec3 edge_normal = nominal.pseudonormal(t, ncv::edge_feature(k));
      Vec3 expected{0, 0, 0};
      for (int axis = 0; axis < 3; ++axis)
        expected[axis] = std::fabs(mid[axis]) == 1 ? mid[axis] : 0;
      CHECK(near(edge_normal, ncv::normalized(expected)));
    }
  }
}

TEST_CASE("nominal: degenerate faces contribute no normal", "[nominal]") {
  // The T-junction crack of the front face (y = 0) of the unit box, closed by the
  // zero-area triangle (0, 1, m).
  ncv::Mesh mesh = fx::box({0, 0, 0}, {1, 1, 1});
  const auto m = static_cast<std::uint32_t>(mesh.vertices.size());
  mesh.vertices.push_back({0.5, 0, 0});
  mesh.triangles[4] = {0, m, 4};
  mesh.triangles.push_back({m, 1, 4});
  mesh.triangles.push_back({0, 1, m});
  const ncv::ReferenceSurface nominal(mesh, "cracked");
  CHECK(nominal.automatic_sign_method() == ncv::SignMethod::pseudonormal);
  CHECK(nominal.face_normal(13) == Vec3(0, 0, 0));
  // At m the degenerate triangle has the largest angle (pi) but no say.
  CHECK(near(nominal.pseudonormal(12, ncv::vertex_feature(0)), {0, -1, 0}));
  // Edge 0-1 joins the bottom face and the degenerate one: the bottom's normal alone.
  CHECK(near(nominal.pseudonormal(13, ncv::edge_feature(0)), {0, 0, -1}));
}

TEST_CASE("nominal: orientation and the automatic sign method", "[nominal]") {
  SECTION("closed and outward: pseudonormal") {
    const ncv::ReferenceSurface nominal(fx::pocketed_block().mesh(1.0), "ok");
    CHECK_FALSE(nominal.flipped());
    CHECK(nominal.automatic_sign_method() == ncv::SignMethod::pseudonormal);
    CHECK(nominal.winding_reason().empty());
  }
  SECTION("closed and inward: flipped, then pseudonormal") {
    const ncv::Mesh inward = fx::flipped(fx::pocketed_block().mesh(1.0));
    const ncv::ReferenceSurface nominal(inward, "inward");
    CHECK(nominal.flipped());
    CHECK(nominal.topology().signed_volume < 0);
    CHECK(nominal.automatic_sign_method() == ncv::SignMethod::pseudonormal);
    for (std::size_t t = 0; t < inward.triangle_count(); ++t) {
      const ncv::TriangleCorners& flipped = nominal.corners(t);
      const Vec3 o = nominal.origin();
      CHECK(flipped[0] == inward.corner(t, 0) - o);
      CHECK(flipped[1] == inward.corner(t, 2) - o);
      CHECK(flipped[2] == inward.corner(t, 1) - o);
    }
    // Normals point out again: the top face (z = 2) has +z.
    const ncv::ReferenceSurface outward(fx::pocketed_block().mesh(1.0), "outward");
    for (std::size_t t = 0; t < inward.triangle_count(); ++t) {
      CHECK(near(nominal.face_normal(t), outward.face_normal(t)));
      for (int k = 0; k < 3; ++k) {
        // Flipping renumbers the slots: match the edges by their end points.
        const ncv::TriangleCorners& tri = nominal.corners(t);
        const ncv::TriangleCorners& out = outward.corners(t);
        for (int j = 0; j < 3; ++j) {
          const bool same_edge = (tri[k] == out[j] && tri[(k + 1) % 3] == out[(j + 1) % 3]) ||
                                 (tri[k] == out[(j + 1) % 3] && tri[(k + 1) % 3] == out[j]);
          if (same_edge) {
            CHECK(near(nominal.pseudonormal(t, ncv::edge_feature(k)),
                       outward.pseudonormal(t, ncv::edge_feature(j))));
          }
        }
      }
    }
  }
  SECTION("open: winding, and says why") {
    ncv::Mesh mesh = fx::box({0, 0, 0}, {1, 1, 1});
    mesh.triangles.resize(10);
    const ncv::ReferenceSurface nominal(mesh, "open");
    CHECK(nominal.automatic_sign_method() == ncv::SignMethod::winding);
    CHECK(nominal.winding_reason().find("boundary") != std::string::npos);
  }
  SECTION("non-manifold: winding") {
    ncv::Mesh mesh = fx::box({0, 0, 0}, {1, 1, 1});
    mesh.triangles.push_back(mesh.triangles[0]);
    const ncv::ReferenceSurface nominal(mesh, "doubled");
    CHECK(nominal.automatic_sign_method() == ncv::SignMethod::winding);
    CHECK(nominal.winding_reason().find("more than two") != std::string::npos);
  }
  SECTION("no volume: winding, not flipped") {
    ncv::Mesh sheet;
    sheet.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    sheet.triangles = {{0, 1, 2}, {0, 2, 1}};
    const ncv::ReferenceSurface nominal(sheet, "sheet");
    CHECK_FALSE(nominal.flipped());
    CHECK(nominal.topology().closed());
    CHECK(nominal.automatic_sign_method() == ncv::SignMethod::winding);
    CHECK(nominal.winding_reason() == "it encloses no volume");
  }
}

TEST_CASE("sign method names round-trip", "[nominal]") {
  for (ncv::SignMethod m : {ncv::SignMethod::automatic, ncv::SignMethod::pseudonormal,
                            ncv::SignMethod::winding, ncv::SignMethod::paper}) {
    CHECK(ncv::parse_name(ncv::kSignMethodNames, ncv::name_of(ncv::kSignMethodNames, m)) == m);
  }
  CHECK(ncv::name_of(ncv::kSignMethodNames, ncv::SignMethod::automatic) == "auto");
  CHECK_FALSE(ncv::parse_name(ncv::kSignMethodNames, "normal").has_value());
  CHECK(ncv::name_of(ncv::kSignMethodNames, static_cast<ncv::SignMethod>(9)) == "unknown");
}

// Corners, face normals and the angle-weighted sums are built in parallel (the sums in
// triangle order): every bit must be the same on any thread count. The torus has more
// triangles than one parallel chunk, so two threads really split the work.
TEST_CASE("nominal: corners and pseudonormals do not depend on the thread count", "[nominal]") {
  const ncv::Mesh torus = fx::torus(5.0, 1.5, 256, 128);
  REQUIRE(torus.triangle_count() > 3 * (1 << 14));
  const auto build = [&](std::size_t threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return ncv::ReferenceSurface(torus, "torus");
  };
  const ncv::ReferenceSurface one = build(1);
  const ncv::ReferenceSurface two = build(2);
  const auto features = {ncv::TriangleFeature::face,    ncv::TriangleFeature::edge0,
                         ncv::TriangleFeature::edge1,   ncv::TriangleFeature::edge2,
                         ncv::TriangleFeature::vertex0, ncv::TriangleFeature::vertex1,
                         ncv::TriangleFeature::vertex2};
  std::size_t differences = 0;
  for (std::size_t t = 0; t < one.triangle_count(); ++t) {
    differences += one.corners(t) != two.corners(t);
    for (const ncv::TriangleFeature feature : features) {
      differences += one.pseudonormal(t, feature) != two.pseudonormal(t, feature);
    }
  }
  CHECK(differences == 0);
  // And they are what the definition gives: unit length, and on a torus the face normal
  // and its corners' normals point the same way.
  for (std::size_t t = 0; t < one.triangle_count(); t += 97) {
    CHECK(std::abs(ncv::norm(one.pseudonormal(t, ncv::TriangleFeature::vertex0)) - 1) < 1e-12);
    CHECK(ncv::dot(one.face_normal(t), one.pseudonormal(t, ncv::TriangleFeature::vertex1)) > 0.9);
  }
}
