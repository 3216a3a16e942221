#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "nominal_fixtures.hpp"
#include "sampling/sample_normals.hpp"

using ncv::Vec3;

TEST_CASE("sample normals: the face's inside a triangle, the area-weighted mean at a vertex",
          "[sampling]") {
  const ncv::SampleSet samples =
      ncv::sample_mesh(ncv::fixtures::box({0, 0, 0}, {1, 2, 3}), 0.5, ncv::SamplingScheme::all);
  // Dirty the heap first: the vertex sums (8 of them) must start from zero, not from the
  // memory a freed array of the same size leaves behind.
  { std::vector<Vec3> garbage(8, Vec3(1e30, -1e30, 7)); }
  const std::vector<Vec3> normals = ncv::sample_normals(samples);
  REQUIRE(normals.size() == samples.sample_count());
  const double inv_sqrt3 = 1 / std::sqrt(3.0);
  for (std::size_t s = 0; s < samples.sample_count(); ++s) {
    const Vec3 p = samples.positions[s];
    INFO("sample at " << p[0] << " " << p[1] << " " << p[2]);
    const bool corner =
        (p[0] == 0 || p[0] == 1) && (p[1] == 0 || p[1] == 2) && (p[2] == 0 || p[2] == 3);
    if (corner) {
      // The box's corners: two triangles on one face meet there and one on each of the others
      // or the reverse; their area-weighted mean is not axis-aligned but points outward.
      for (int axis = 0; axis < 3; ++axis) {
        const double outward = p[axis] == 0 ? -1 : 1;
        CHECK(normals[s][axis] * outward > 0);
      }
      CHECK(ncv::norm(normals[s]) == Approx(1));
      CHECK(std::fabs(normals[s][0]) < 1 - 1e-3);
      CHECK(std::fabs(normals[s][0]) > 0.1 * inv_sqrt3);
    } else {
      CHECK(ncv::norm(normals[s]) == Approx(1));
    }
  }
}
