// Meshes and sample sets shared by the statistics, region and colouring tests.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "files/distance_file.hpp"
#include "mesh/mesh.hpp"
#include "sampling/sampling.hpp"

namespace ncv::test {

// The square [0, size]^2 in the plane z = 0, cut into cells x cells squares of two
// triangles each, normals +z.
inline Mesh flat_grid(std::uint32_t cells, double size) {
  Mesh mesh;
  const double h = size / cells;
  for (std::uint32_t y = 0; y <= cells; ++y) {
    for (std::uint32_t x = 0; x <= cells; ++x) mesh.vertices.push_back({x * h, y * h, 0});
  }
  const auto at = [&](std::uint32_t x, std::uint32_t y) { return y * (cells + 1) + x; };
  for (std::uint32_t y = 0; y < cells; ++y) {
    for (std::uint32_t x = 0; x < cells; ++x) {
      mesh.triangles.push_back({at(x, y), at(x + 1, y), at(x + 1, y + 1)});
      mesh.triangles.push_back({at(x, y), at(x + 1, y + 1), at(x, y + 1)});
    }
  }
  return mesh;
}

// The box [0,sx] x [0,sy] x [0,sz] with every face on its own four vertices, so that a
// value per face is a consistent value per sample. Faces in the order -x, +x, -y, +y, -z,
// +z, two triangles each.
inline Mesh unwelded_box(double sx, double sy, double sz) {
  Mesh mesh;
  const auto face = [&](Vec3 origin, Vec3 u, Vec3 v) {
    const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), {origin, origin + u, origin + u + v, origin + v});
    mesh.triangles.push_back({base, base + 1, base + 2});
    mesh.triangles.push_back({base, base + 2, base + 3});
  };
  face({0, 0, 0}, {0, 0, sz}, {0, sy, 0});
  face({sx, 0, 0}, {0, sy, 0}, {0, 0, sz});
  face({0, 0, 0}, {sx, 0, 0}, {0, 0, sz});
  face({0, sy, 0}, {0, 0, sz}, {sx, 0, 0});
  face({0, 0, 0}, {0, sy, 0}, {sx, 0, 0});
  face({0, 0, sz}, {sx, 0, 0}, {0, sy, 0});
  return mesh;
}

// One distance per sample from a function of its position.
inline std::vector<double> distances_of(const SampleSet& samples,
                                        const std::function<double(Vec3)>& field) {
  std::vector<double> d(samples.sample_count());
  for (std::size_t s = 0; s < d.size(); ++s) d[s] = field(samples.positions[s]);
  return d;
}

// `mesh` sampled at `step` with the linear field d = x / 10 - 0.2 as its forward distances,
// against a two-triangle plate nominal: the report tests' part.
inline DistanceSet linear_field_part(Mesh mesh, double step, const std::string& source) {
  DistanceSet set;
  set.samples = sample_mesh(std::move(mesh), step, SamplingScheme::all);
  set.samples.source = source;
  for (const Vec3& p : set.samples.positions) {
    set.field.distance.push_back(p[0] / 10 - 0.2);
    set.field.closest_face.push_back(0);
  }
  set.reference = {"plate_nominal.stl", 42, 2, {}};
  set.sign_method = "pseudonormal";
  set.search = "grid";
  return set;
}

}  // namespace ncv::test
