// An indexed triangle mesh as plain arrays: welded vertices (double precision) and
// triangles as vertex-index triples. Readers produce it, every algorithm consumes it.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/bounding_box.hpp"
#include "geometry/vec3.hpp"

namespace ncv {

using Triangle = std::array<std::uint32_t, 3>;

struct Mesh {
  std::vector<Vec3> vertices;
  std::vector<Triangle> triangles;

  std::size_t vertex_count() const { return vertices.size(); }
  std::size_t triangle_count() const { return triangles.size(); }
  Vec3 corner(std::size_t triangle, int k) const { return vertices[triangles[triangle][k]]; }
};

// A triangle that names one vertex twice: it has no area and no edges of its own.
constexpr bool repeats_corner(const Triangle& t) {
  return t[0] == t[1] || t[1] == t[2] || t[2] == t[0];
}

// Twice-area normal (not normalised) of triangle t: cross(B - A, C - A).
Vec3 area_vector(const Mesh& mesh, std::size_t triangle);
double triangle_area(const Mesh& mesh, std::size_t triangle);
double surface_area(const Mesh& mesh);
BoundingBox bounding_box(const Mesh& mesh);
// Content hash of the geometry (vertex coordinates and triangle indices), XXH3-64.
std::uint64_t mesh_hash(const Mesh& mesh);
// What every mesh ncverify measures holds, whether read from a file or handed over in
// memory: at least one triangle, fewer than 2^31, every vertex finite and within
// kMaxCoordinate. Throws InputError naming `source` otherwise.
void check_mesh(const Mesh& mesh, const std::string& source);

}  // namespace ncv
