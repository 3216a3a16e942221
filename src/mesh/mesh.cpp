#include "mesh/mesh.hpp"

#include <fmt/format.h>
#include <xxhash.h>

#include <limits>
#include <span>

#include "geometry/coordinate_limit.hpp"
#include "util/error.hpp"
#include "util/ordered_reduce.hpp"
#include "util/serial_sum.hpp"

namespace ncv {

Vec3 area_vector(const Mesh& mesh, std::size_t triangle) {
  const Vec3 a = mesh.corner(triangle, 0);
  return cross(mesh.corner(triangle, 1) - a, mesh.corner(triangle, 2) - a);
}

double triangle_area(const Mesh& mesh, std::size_t triangle) {
  return 0.5 * norm(area_vector(mesh, triangle));
}

double surface_area(const Mesh& mesh) {
  return serial_sum(mesh.triangle_count(), [&](std::size_t t) { return triangle_area(mesh, t); });
}

// In blocks side by side, combined in block order: the box of a serial loop, to the sign of
// a zero (std::min keeps the first of equal values). A run asks for the workpiece's box
// about ten times, 2.5 ms each for 625 k vertices on one thread.
BoundingBox bounding_box(const Mesh& mesh) {
  const std::span<const Vec3> points = mesh.vertices;
  return ordered_reduce(
      points.size(), std::size_t{1} << 16, BoundingBox{},
      [&](std::size_t begin, std::size_t end) {
        return BoundingBox::of(points.subspan(begin, end - begin));
      },
      [](BoundingBox& box, const BoundingBox& part) { box.extend(part); });
}

std::uint64_t mesh_hash(const Mesh& mesh) {
  XXH3_state_t* state = XXH3_createState();
  XXH3_64bits_reset(state);
  XXH3_64bits_update(state, mesh.vertices.data(), mesh.vertices.size() * sizeof(Vec3));
  XXH3_64bits_update(state, mesh.triangles.data(), mesh.triangles.size() * sizeof(Triangle));
  const std::uint64_t hash = XXH3_64bits_digest(state);
  XXH3_freeState(state);
  return hash;
}

void check_mesh(const Mesh& mesh, const std::string& source) {
  if (mesh.triangles.empty()) throw InputError(source, "the mesh has no triangles");
  for (const Vec3& p : mesh.vertices) {
    if (!is_finite(p)) throw InputError(source, "a vertex has a NaN or infinite coordinate");
    // The bound the distance step holds nominal and query points to (squares of such
    // coordinates would overflow); a workpiece beyond it used to get as far as a sampling
    // step of "inf".
    if (max_abs(p) > kMaxCoordinate) {
      throw InputError(source, fmt::format("a vertex lies beyond {}", kMaxCoordinate));
    }
  }
  if (mesh.triangles.size() > std::numeric_limits<std::uint32_t>::max() / 2) {
    throw InputError(source, "too many triangles (more than 2^31)");
  }
}

}  // namespace ncv
