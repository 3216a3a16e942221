#include "mesh/halfedge_mesh.hpp"

#include <algorithm>

#include "util/parallel_over.hpp"

namespace ncv {
namespace {

using VertexHandle = TriMesh::VertexHandle;
using HalfedgeHandle = TriMesh::HalfedgeHandle;
using FaceHandle = TriMesh::FaceHandle;

constexpr std::size_t kGrain = std::size_t{1} << 14;

VertexHandle vertex_handle(std::uint32_t v) {
  return VertexHandle(static_cast<int>(v));
}

}  // namespace

bool holds_as_halfedge_mesh(const Mesh& mesh, const TopologyReport& topology) {
  if (topology.non_manifold_edges != 0 || topology.misoriented_edges != 0 ||
      topology.non_manifold_vertices != 0) {
    return false;
  }
  return std::none_of(mesh.triangles.begin(), mesh.triangles.end(), repeats_corner);
}

HalfedgeHandle slot_halfedge(const EdgeIncidence& incidence, std::uint32_t slot) {
  const std::uint32_t edge = incidence.edge_of_slot[slot];
  const std::uint32_t first = incidence.edge_begin[edge];
  const bool lower = incidence.slot_count(edge) == 1 ||
                     slot == std::min(incidence.slots[first], incidence.slots[first + 1]);
  return HalfedgeHandle(static_cast<int>(2 * edge + (lower ? 0 : 1)));
}

// Every link is written by exactly one iteration (a halfedge's next, and with it the next's
// prev, by the triangle or boundary edge it belongs to), so the loops run in parallel.
TriMesh halfedge_mesh(const Mesh& mesh, const EdgeIncidence& incidence) {
  TriMesh result;
  result.resize(mesh.vertex_count(), incidence.edge_count(), mesh.triangle_count());
  parallel_over(mesh.vertex_count(), kGrain, [&](std::size_t v) {
    result.point(vertex_handle(static_cast<std::uint32_t>(v))) = mesh.vertices[v];
  });
  parallel_over(mesh.triangle_count(), kGrain, [&](std::size_t t) {
    const Triangle& corners = mesh.triangles[t];
    const auto face = FaceHandle(static_cast<int>(t));
    for (std::uint32_t k = 0; k < 3; ++k) {
      const auto slot = static_cast<std::uint32_t>(3 * t + k);
      const HalfedgeHandle h = slot_halfedge(incidence, slot);
      result.set_vertex_handle(h, vertex_handle(corners[(k + 1) % 3]));
      result.set_face_handle(h, face);
      result.set_next_halfedge_handle(h, slot_halfedge(incidence, slot / 3 * 3 + (slot + 1) % 3));
    }
    result.set_halfedge_handle(face, slot_halfedge(incidence, static_cast<std::uint32_t>(3 * t)));
  });
  // Each vertex's outgoing halfedge: that of its first corner, in triangle order. Serial:
  // several corners share a vertex (about 10 ms for a million triangles).
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    for (std::uint32_t k = 0; k < 3; ++k) {
      const VertexHandle v = vertex_handle(mesh.triangles[t][k]);
      if (!result.halfedge_handle(v).is_valid()) {
        result.set_halfedge_handle(v,
                                   slot_halfedge(incidence, static_cast<std::uint32_t>(3 * t + k)));
      }
    }
  }
  // The boundary halfedge of an edge with one triangle runs against it. A boundary vertex
  // keeps its outgoing boundary halfedge, as OpenMesh's add_face leaves it (its circulators
  // and is_boundary(vertex) rely on that); with one fan per vertex it has exactly one, so
  // the next of a boundary halfedge is the outgoing boundary halfedge of its end.
  const auto boundary_slot = [&](std::size_t edge) {
    return incidence.slot_count(edge) == 1 ? incidence.slots[incidence.edge_begin[edge]] : kNoEdge;
  };
  const auto corner = [&](std::uint32_t slot, std::uint32_t step) {
    return mesh.triangles[slot / 3][(slot % 3 + step) % 3];
  };
  parallel_over(incidence.edge_count(), kGrain, [&](std::size_t edge) {
    const std::uint32_t slot = boundary_slot(edge);
    if (slot == kNoEdge) return;
    const auto h = HalfedgeHandle(static_cast<int>(2 * edge + 1));
    result.set_vertex_handle(h, vertex_handle(corner(slot, 0)));
    result.set_halfedge_handle(vertex_handle(corner(slot, 1)), h);
  });
  parallel_over(incidence.edge_count(), kGrain, [&](std::size_t edge) {
    const std::uint32_t slot = boundary_slot(edge);
    if (slot == kNoEdge) return;
    const auto h = HalfedgeHandle(static_cast<int>(2 * edge + 1));
    result.set_next_halfedge_handle(h, result.halfedge_handle(vertex_handle(corner(slot, 0))));
  });
  return result;
}

}  // namespace ncv
