// Meshes for the distance, grid, topology and winding-number tests: closed solids with
// known geometry, open and mis-oriented variants, and random soups.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <numeric>
#include <random>
#include <set>
#include <tuple>
#include <vector>

#include "geometry/closest_point.hpp"
#include "mesh/mesh.hpp"

namespace ncv::fixtures {

// A solid made of unit voxels of a lattice, scaled by `scale`: its boundary, two triangles
// per exposed voxel face, outward and consistently oriented, vertices welded on the
// lattice. Closed and manifold as long as no two voxels touch only along an edge or corner.
class VoxelSolid {
 public:
  void fill(int x0, int y0, int z0, int x1, int y1, int z1) {
    for (int x = x0; x < x1; ++x)
      for (int y = y0; y < y1; ++y)
        for (int z = z0; z < z1; ++z) voxels_.insert({x, y, z});
  }
  void carve(int x0, int y0, int z0, int x1, int y1, int z1) {
    for (int x = x0; x < x1; ++x)
      for (int y = y0; y < y1; ++y)
        for (int z = z0; z < z1; ++z) voxels_.erase({x, y, z});
  }
  // Closed point-in-solid test: the oracle for signs.
  bool contains(Vec3 p, double scale) const {
    const auto cell = [&](double v) { return static_cast<int>(std::floor(v / scale)); };
    return voxels_.count({cell(p[0]), cell(p[1]), cell(p[2])}) > 0;
  }

  Mesh mesh(double scale) const {
    Mesh mesh;
    std::map<std::array<int, 3>, std::uint32_t> index;
    const auto vertex = [&](std::array<int, 3> v) {
      auto [it, inserted] = index.try_emplace(v, static_cast<std::uint32_t>(mesh.vertices.size()));
      if (inserted) mesh.vertices.push_back({v[0] * scale, v[1] * scale, v[2] * scale});
      return it->second;
    };
    for (const auto& [x, y, z] : voxels_) {
      for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
          std::array<int, 3> neighbour{x, y, z};
          neighbour[axis] += side ? 1 : -1;
          if (voxels_.count({neighbour[0], neighbour[1], neighbour[2]})) continue;
          emit_face(mesh, vertex, {x, y, z}, axis, side);
        }
      }
    }
    return mesh;
  }

 private:
  template <class Vertex>
  static void emit_face(Mesh& mesh, Vertex& vertex, std::array<int, 3> cell, int axis, int side) {
    const int u = (axis + 1) % 3;
    const int v = (axis + 2) % 3;
    std::array<std::array<int, 3>, 4> corners;
    for (int c = 0; c < 4; ++c) {
      corners[c] = cell;
      corners[c][axis] += side;
      corners[c][u] += (c == 1 || c == 2);
      corners[c][v] += (c >= 2);
    }
    // (u, v, axis) is right-handed, so corners 0,1,2,3 run counter-clockwise seen from +axis.
    std::array<std::uint32_t, 4> q;
    for (int c = 0; c < 4; ++c) q[c] = vertex(corners[c]);
    if (side) {
      mesh.triangles.push_back({q[0], q[1], q[2]});
      mesh.triangles.push_back({q[0], q[2], q[3]});
    } else {
      mesh.triangles.push_back({q[0], q[2], q[1]});
      mesh.triangles.push_back({q[0], q[3], q[2]});
    }
  }

  std::set<std::tuple<int, int, int>> voxels_;
};

// The axis-aligned box [lo, hi] as 12 outward triangles.
inline Mesh box(Vec3 lo, Vec3 hi) {
  Mesh mesh;
  for (int i = 0; i < 8; ++i) {
    mesh.vertices.push_back({i & 1 ? hi[0] : lo[0], i & 2 ? hi[1] : lo[1], i & 4 ? hi[2] : lo[2]});
  }
  mesh.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return mesh;
}

// A 4 x 4 x 2 block (scaled) with a 2 x 2 x 1 pocket in its top: sharp concave edges and
// corners at the pocket floor, convex ones at its rim.
inline VoxelSolid pocketed_block() {
  VoxelSolid solid;
  solid.fill(0, 0, 0, 4, 4, 2);
  solid.carve(1, 1, 1, 3, 3, 2);
  return solid;
}

// Torus around z with radii major > minor, nu x nv quads split in two.
inline Mesh torus(double major, double minor, int nu, int nv) {
  Mesh mesh;
  for (int i = 0; i < nu; ++i) {
    const double u = 2 * std::numbers::pi * i / nu;
    for (int j = 0; j < nv; ++j) {
      const double v = 2 * std::numbers::pi * j / nv;
      const double ring = major + minor * std::cos(v);
      mesh.vertices.push_back({ring * std::cos(u), ring * std::sin(u), minor * std::sin(v)});
    }
  }
  const auto at = [&](int i, int j) {
    return static_cast<std::uint32_t>((i % nu) * nv + (j % nv));
  };
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return mesh;
}

// `mesh` with its triangles shuffled and its vertices numbered by first use, as a weld of a
// file with its facets in random order numbers them.
inline Mesh shuffled_facets(const Mesh& mesh, std::uint64_t seed) {
  std::vector<std::size_t> order(mesh.triangle_count());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::shuffle(order.begin(), order.end(), std::mt19937_64(seed));
  Mesh out;
  std::vector<std::uint32_t> renamed(mesh.vertex_count(), ~0u);
  for (const std::size_t t : order) {
    Triangle triangle{};
    for (int k = 0; k < 3; ++k) {
      std::uint32_t& v = renamed[mesh.triangles[t][k]];
      if (v == ~0u) {
        v = static_cast<std::uint32_t>(out.vertices.size());
        out.vertices.push_back(mesh.vertices[mesh.triangles[t][k]]);
      }
      triangle[k] = v;
    }
    out.triangles.push_back(triangle);
  }
  return out;
}

// `count` unconnected triangles in [0, 1]^3 with edges up to `size`.
inline Mesh random_soup(std::mt19937_64& rng, std::size_t count, double size) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_real_distribution<double> offset(-size, size);
  Mesh mesh;
  for (std::size_t t = 0; t < count; ++t) {
    const Vec3 a{unit(rng), unit(rng), unit(rng)};
    const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
    mesh.vertices.push_back(a);
    mesh.vertices.push_back(a + Vec3{offset(rng), offset(rng), offset(rng)});
    mesh.vertices.push_back(a + Vec3{offset(rng), offset(rng), offset(rng)});
    mesh.triangles.push_back({first, first + 1, first + 2});
  }
  return mesh;
}

// Each triangle's corners, as the winding number and the arrays' pseudonormals read them.
inline Mesh translated(Mesh mesh, Vec3 by) {
  for (Vec3& v : mesh.vertices) v += by;
  return mesh;
}

inline Mesh flipped(Mesh mesh) {
  for (Triangle& t : mesh.triangles) std::swap(t[1], t[2]);
  return mesh;
}

inline Vec3 random_point(std::mt19937_64& rng, Vec3 lo, Vec3 hi) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  return {lo[0] + unit(rng) * (hi[0] - lo[0]), lo[1] + unit(rng) * (hi[1] - lo[1]),
          lo[2] + unit(rng) * (hi[2] - lo[2])};
}

inline Vec3 random_direction(std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  return normalized(Vec3{normal(rng), normal(rng), normal(rng)});
}

// The point A + u (B - A) + v (C - A) of triangle ABC, folded back into it when u + v > 1.
inline Vec3 point_on(const TriangleCorners& t, double u, double v) {
  if (u + v > 1) {
    u = 1 - u;
    v = 1 - v;
  }
  return t[0] + u * (t[1] - t[0]) + v * (t[2] - t[0]);
}

// A uniformly random point of triangle t.
inline Vec3 random_point_on(std::mt19937_64& rng, const Mesh& mesh, std::size_t t) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double u = unit(rng), v = unit(rng);
  if (u + v > 1) u = 1 - u, v = 1 - v;
  const Vec3 a = mesh.corner(t, 0);
  return a + u * (mesh.corner(t, 1) - a) + v * (mesh.corner(t, 2) - a);
}

// A block [0, length] x [0, width] x [0, height] whose top is `scallops` ball-end scallops
// across x: circular arcs of radius `radius`, `facets` chords each, their troughs at `height`
// and their cusps above; the top in long strips across y, as CAM meshes leave it. Closed,
// outward, welded.
inline Mesh scalloped_block(double length, double width, double height, int scallops, double radius,
                            int facets) {
  std::vector<std::pair<double, double>> profile;  // (x, z) along the top
  const double pitch = length / scallops;
  for (int s = 0; s < scallops; ++s) {
    for (int f = 0; f < facets; ++f) {
      const double x = s * pitch + pitch * f / facets;
      const double offset = x - (s + 0.5) * pitch;  // from the trough under the ball's centre
      profile.push_back({x, height + radius - std::sqrt(radius * radius - offset * offset)});
    }
  }
  // The cusp at x = length, as at x = 0.
  profile.push_back({length, profile.front().second});
  Mesh mesh;
  const auto vertex = [&](double x, double y, double z) {
    mesh.vertices.push_back({x, y, z});
    return static_cast<std::uint32_t>(mesh.vertices.size() - 1);
  };
  const std::size_t n = profile.size();
  std::vector<std::uint32_t> top0, top1, bottom0, bottom1;
  for (const auto& [x, z] : profile) {
    top0.push_back(vertex(x, 0, z));
    top1.push_back(vertex(x, width, z));
    bottom0.push_back(vertex(x, 0, 0));
    bottom1.push_back(vertex(x, width, 0));
  }
  // A quad as two triangles, turned to face `outward`.
  const auto quad = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d,
                        Vec3 outward) {
    const Vec3 normal =
        cross(mesh.vertices[b] - mesh.vertices[a], mesh.vertices[c] - mesh.vertices[a]);
    if (dot(normal, outward) < 0) std::swap(b, d);
    mesh.triangles.push_back({a, b, c});
    mesh.triangles.push_back({a, c, d});
  };
  for (std::size_t i = 0; i + 1 < n; ++i) {
    quad(top0[i], top0[i + 1], top1[i + 1], top1[i], {0, 0, 1});
    quad(bottom0[i], bottom1[i], bottom1[i + 1], bottom0[i + 1], {0, 0, -1});
    quad(bottom0[i], bottom0[i + 1], top0[i + 1], top0[i], {0, -1, 0});
    quad(bottom1[i], top1[i], top1[i + 1], bottom1[i + 1], {0, 1, 0});
  }
  quad(bottom0[0], top0[0], top1[0], bottom1[0], {-1, 0, 0});
  quad(bottom0[n - 1], bottom1[n - 1], top1[n - 1], top0[n - 1], {1, 0, 0});
  return mesh;
}

}  // namespace ncv::fixtures
