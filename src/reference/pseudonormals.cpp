#include "reference/pseudonormals.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace ncv {
namespace {

template <class Body>
void parallel_over(std::size_t count, std::size_t grain, Body body) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, grain),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i) body(i);
                    });
}

double corner_angle(Vec3 apex, Vec3 b, Vec3 c) {
  const Vec3 u = b - apex;
  const Vec3 v = c - apex;
  return std::atan2(norm(cross(u, v)), dot(u, v));
}

bool is_zero(Vec3 v) {
  return v == Vec3(0, 0, 0);  // a real unit normal is never zero
}

void normalize_all(std::vector<Vec3>& vectors) {
  parallel_over(vectors.size(), 1 << 14,
                [&](std::size_t i) { vectors[i] = normalized(vectors[i]); });
}

}  // namespace

Buffer<Vec3> face_normals(std::span<const TriangleCorners> corners) {
  Buffer<Vec3> normals(corners.size());
  parallel_over(corners.size(), 1 << 12, [&](std::size_t t) {
    const auto& [a, b, c] = corners[t];
    normals[t] = is_degenerate_triangle(a, b, c) ? Vec3(0, 0, 0) : normalized(cross(b - a, c - a));
  });
  return normals;
}

// Per face its corners from its halfedges (the first runs from corner 0 to corner 1), per
// vertex its faces from its outgoing halfedges, per edge its faces from its two halfedges:
// every element on its own, so all three loops run in parallel. A vertex's terms are sorted
// by face before they are added, as the arrays' triangle-order loop adds them.
Pseudonormals halfedge_pseudonormals(const TriMesh& mesh, const EdgeIncidence& incidence) {
  Pseudonormals normals;
  std::vector<TriangleCorners> corners(mesh.n_faces());
  parallel_over(mesh.n_faces(), 1 << 12, [&](std::size_t f) {
    const auto h = mesh.halfedge_handle(TriMesh::FaceHandle(static_cast<int>(f)));
    corners[f] = {mesh.point(mesh.from_vertex_handle(h)), mesh.point(mesh.to_vertex_handle(h)),
                  mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h)))};
  });
  normals.face = face_normals(corners);

  normals.vertex.resize(mesh.n_vertices());
  parallel_over(mesh.n_vertices(), 1 << 12, [&](std::size_t v) {
    const auto vertex = TriMesh::VertexHandle(static_cast<int>(v));
    std::vector<std::pair<int, Vec3>> terms;
    terms.reserve(8);
    const Vec3 apex = mesh.point(vertex);
    for (const auto h : mesh.voh_range(vertex)) {
      if (mesh.is_boundary(h)) continue;
      const int face = mesh.face_handle(h).idx();
      const Vec3 n = normals.face[static_cast<std::size_t>(face)];
      if (is_zero(n)) continue;
      const double angle =
          corner_angle(apex, mesh.point(mesh.to_vertex_handle(h)),
                       mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h))));
      terms.emplace_back(face, angle * n);
    }
    std::sort(terms.begin(), terms.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    Vec3 sum(0, 0, 0);
    for (const auto& term : terms) sum += term.second;
    normals.vertex[v] = normalized(sum);
  });

  normals.edge.resize(mesh.n_edges());
  parallel_over(mesh.n_edges(), 1 << 14, [&](std::size_t e) {
    std::array<int, 2> faces{};
    for (int side = 0; side < 2; ++side) {
      faces[side] = mesh.face_handle(TriMesh::HalfedgeHandle(static_cast<int>(2 * e + side))).idx();
    }
    std::sort(faces.begin(), faces.end());
    Vec3 sum(0, 0, 0);
    for (const int face : faces) {
      if (face >= 0 && !is_zero(normals.face[static_cast<std::size_t>(face)])) {
        sum += normals.face[static_cast<std::size_t>(face)];
      }
    }
    normals.edge[e] = normalized(sum);
  });
  normals.edge_of_slot = incidence.edge_of_slot;
  return normals;
}

// Face normals and corner angles in parallel; the angle-weighted sums stay serial, in
// triangle order, so they do not depend on the thread count. The angles are kept rather
// than their products with the normal: a third of the memory to write and read.
Pseudonormals array_pseudonormals(const Mesh& mesh, std::span<const TriangleCorners> corners,
                                  const EdgeIncidence& incidence) {
  Pseudonormals normals;
  const std::size_t triangles = mesh.triangle_count();
  normals.face = face_normals(corners);
  normals.vertex.assign(mesh.vertex_count(), Vec3(0, 0, 0));
  normals.edge.assign(incidence.edge_count(), Vec3(0, 0, 0));
  normals.edge_of_slot = incidence.edge_of_slot;
  Buffer<std::array<double, 3>> corner_angles(triangles);
  parallel_over(triangles, 1 << 12, [&](std::size_t t) {
    if (is_zero(normals.face[t])) return;
    const auto& [a, b, c] = corners[t];
    corner_angles[t] = {corner_angle(a, b, c), corner_angle(b, c, a), corner_angle(c, a, b)};
  });
  for (std::size_t t = 0; t < triangles; ++t) {
    const Vec3 n = normals.face[t];
    if (is_zero(n)) continue;
    const Triangle& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) normals.vertex[tri[k]] += corner_angles[t][k] * n;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t edge = normals.edge_of_slot[3 * t + k];
      if (edge != kNoEdge) normals.edge[edge] += n;
    }
  }
  normalize_all(normals.vertex);
  normalize_all(normals.edge);
  return normals;
}

}  // namespace ncv
