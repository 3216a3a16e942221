// Connectivity of a triangle mesh: which triangle edges share an undirected edge, and what
// that says about the surface (closed, manifold, consistently oriented, outward).
//
// Triangle edges are addressed by slot 3t + k: edge k of triangle t runs from corner k to
// corner (k + 1) % 3. Triangles that repeat a vertex index carry no surface and take no
// part in the edge structure (they are counted as degenerate): a triangle (a, a, b) would
// otherwise use edge {a, b} once in each direction and hide a hole.
//
// Built by bucketing slots by their lower vertex index and sorting each small bucket (the
// buckets in parallel), so it is linear in practice and needs no hash map: about 30 bytes
// per triangle, and 24 more while it is built.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "mesh/mesh.hpp"
#include "util/buffer.hpp"

namespace ncv {

inline constexpr std::uint32_t kNoEdge = std::numeric_limits<std::uint32_t>::max();

// Buffers, every element written by build_edge_incidence's parallel loops (zero-filling
// the 1.25 M-triangle finishing workpiece's first, on one thread, took 24 ms).
struct EdgeIncidence {
  Buffer<std::uint32_t> edge_of_slot;  // per slot: its undirected edge, or kNoEdge
  Buffer<std::uint32_t> edge_begin;    // per edge + 1: range of `slots`
  Buffer<std::uint32_t> slots;         // slots grouped by edge, ascending within one

  std::size_t edge_count() const { return edge_begin.empty() ? 0 : edge_begin.size() - 1; }
  std::uint32_t slot_count(std::size_t edge) const {
    return edge_begin[edge + 1] - edge_begin[edge];
  }
};

struct TopologyReport {
  std::uint64_t triangles = 0;
  std::uint64_t edges = 0;
  std::uint64_t boundary_edges = 0;         // used by one triangle
  std::uint64_t non_manifold_edges = 0;     // used by three or more
  std::uint64_t misoriented_edges = 0;      // not used equally often in both directions
  std::uint64_t non_manifold_vertices = 0;  // more than one fan of triangles meets there
  std::uint64_t degenerate_triangles = 0;   // repeated corner or (nearly) zero area
  std::uint64_t duplicate_triangles = 0;    // same three vertices as an earlier triangle
  double signed_volume = 0;                 // > 0 for an outward-oriented closed surface

  bool operator==(const TopologyReport&) const = default;
  bool closed() const { return boundary_edges == 0 && non_manifold_edges == 0; }
  bool manifold() const { return non_manifold_edges == 0 && non_manifold_vertices == 0; }
  bool consistently_oriented() const { return misoriented_edges == 0; }
  bool outward() const { return signed_volume > 0; }
};

// True when a triangle has no usable normal: its height over its longest edge is at most
// 1e-10 of that edge (|(b - a) x (c - a)| <= 1e-10 * longest^2), where the direction of the
// cross product is dominated by rounding.
bool is_degenerate_triangle(Vec3 a, Vec3 b, Vec3 c);

EdgeIncidence build_edge_incidence(const Mesh& mesh);
TopologyReport analyse_topology(const Mesh& mesh, const EdgeIncidence& incidence);

}  // namespace ncv
