#include "reference/reference_surface.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "util/error.hpp"

namespace ncv {
namespace {

void check_usable(const Mesh& mesh, const std::string& source) {
  if (mesh.triangle_count() == 0) throw InputError(source, "the nominal mesh has no triangles");
  if (mesh.triangle_count() > kMaxReferenceTriangles) {
    throw InputError(source, fmt::format("the nominal mesh has {} triangles, more than {}",
                                         mesh.triangle_count(), kMaxReferenceTriangles));
  }
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const Vec3 p = mesh.vertices[v];
    if (!is_finite(p)) throw InputError(source, fmt::format("nominal vertex {} is not finite", v));
    if (max_abs(p) > kMaxCoordinate) {
      throw InputError(source, fmt::format("nominal vertex {} lies beyond {}", v, kMaxCoordinate));
    }
  }
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    for (std::uint32_t index : mesh.triangles[t]) {
      if (index >= mesh.vertex_count()) {
        throw InputError(source, fmt::format("nominal triangle {} refers to vertex {} of {}", t,
                                             index, mesh.vertex_count()));
      }
    }
  }
}

double corner_angle(Vec3 apex, Vec3 b, Vec3 c) {
  const Vec3 u = b - apex;
  const Vec3 v = c - apex;
  return std::atan2(norm(cross(u, v)), dot(u, v));
}

// Rounding alone gives a flat or inside-out-and-back mesh a signed volume of about 1e-16
// of its diagonal cubed; only volumes well beyond that say anything about orientation.
double volume_tolerance(const BoundingBox& box) {
  const double diagonal = box.diagonal();
  return 1e-9 * diagonal * diagonal * diagonal;
}

std::string describe_defects(const TopologyReport& t, double volume_tolerance) {
  std::string reason;
  const auto add = [&reason](std::uint64_t count, const char* what) {
    if (count == 0) return;
    if (!reason.empty()) reason += ", ";
    reason += fmt::format("{} {}", count, what);
  };
  add(t.boundary_edges, "boundary edges (open)");
  add(t.non_manifold_edges, "edges with more than two triangles");
  add(t.non_manifold_vertices, "non-manifold vertices");
  add(t.misoriented_edges, "inconsistently oriented edges");
  if (reason.empty() && std::fabs(t.signed_volume) <= volume_tolerance) {
    reason = "it encloses no volume";
  }
  return reason;
}

void normalize_all(std::vector<Vec3>& vectors) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vectors.size(), 1 << 14),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i < range.end(); ++i)
                        vectors[i] = normalized(vectors[i]);
                    });
}

}  // namespace

ReferenceSurface::ReferenceSurface(Mesh mesh, const std::string& source) {
  check_usable(mesh, source);
  origin_ = bounding_box(mesh).center();
  local_ = std::move(mesh);
  for (Vec3& v : local_.vertices) v = to_local(v);
  local_bounds_ = bounding_box(local_);

  EdgeIncidence incidence = build_edge_incidence(local_);
  topology_ = analyse_topology(local_, incidence);
  orient_outward(source);
  if (flipped_) {
    // (v0, v2, v1): slot 0 now runs along the old edge 2 and slot 2 along the old edge 0.
    for (std::size_t t = 0; t < local_.triangle_count(); ++t) {
      std::swap(incidence.edge_of_slot[3 * t], incidence.edge_of_slot[3 * t + 2]);
    }
  }
  choose_sign_method(source);

  copy_corners();
  compute_normals(incidence);
}

// Into an uninitialised buffer, in parallel: zero-filling 72 bytes per triangle first, on
// one thread, took as long as the copy (a 968 k-triangle nominal: 54 ms).
void ReferenceSurface::copy_corners() {
  corners_.resize(local_.triangle_count());
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, corners_.size(), 1 << 14),
      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t t = range.begin(); t < range.end(); ++t) {
          corners_[t] = {local_.corner(t, 0), local_.corner(t, 1), local_.corner(t, 2)};
        }
      });
}

void ReferenceSurface::orient_outward(const std::string& source) {
  if (!(topology_.signed_volume < -volume_tolerance(local_bounds_))) return;
  for (Triangle& t : local_.triangles) std::swap(t[1], t[2]);
  flipped_ = true;
  spdlog::warn("{}: the nominal is oriented inward (signed volume {}); flipped all triangles",
               source, topology_.signed_volume);
}

void ReferenceSurface::choose_sign_method(const std::string& source) {
  winding_reason_ = describe_defects(topology_, volume_tolerance(local_bounds_));
  if (winding_reason_.empty()) return;
  automatic_sign_ = SignMethod::winding;
  spdlog::warn(
      "{}: the nominal is not a closed oriented solid ({}); the automatic sign uses the "
      "generalized winding number",
      source, winding_reason_);
}

void ReferenceSurface::compute_normals(const EdgeIncidence& incidence) {
  const std::size_t triangles = local_.triangle_count();
  face_normals_.resize(triangles);
  vertex_normals_.assign(local_.vertex_count(), Vec3(0, 0, 0));
  edge_normals_.assign(incidence.edge_count(), Vec3(0, 0, 0));
  edge_of_slot_ = incidence.edge_of_slot;
  // Face normals and corner angles in parallel; the angle-weighted sums below stay serial,
  // in triangle order, so they do not depend on the thread count. The angles are kept
  // rather than their products with the normal: a third of the memory to write and read.
  Buffer<std::array<double, 3>> corner_angles(triangles);
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, triangles, 1 << 12),
      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t t = range.begin(); t < range.end(); ++t) {
          const auto& [a, b, c] = corners_[t];
          if (is_degenerate_triangle(a, b, c)) {
            face_normals_[t] = Vec3(0, 0, 0);
            continue;
          }
          face_normals_[t] = normalized(cross(b - a, c - a));
          corner_angles[t] = {corner_angle(a, b, c), corner_angle(b, c, a), corner_angle(c, a, b)};
        }
      });
  for (std::size_t t = 0; t < triangles; ++t) {
    if (face_normals_[t] == Vec3(0, 0, 0))
      continue;  // degenerate (a real unit normal is never zero)
    const Vec3 n = face_normals_[t];
    const Triangle& tri = local_.triangles[t];
    for (int k = 0; k < 3; ++k) vertex_normals_[tri[k]] += corner_angles[t][k] * n;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t edge = edge_of_slot_[3 * t + k];
      if (edge != kNoEdge) edge_normals_[edge] += n;
    }
  }
  normalize_all(vertex_normals_);
  normalize_all(edge_normals_);
}

Vec3 ReferenceSurface::pseudonormal(std::size_t triangle, TriangleFeature feature) const {
  if (is_vertex(feature)) {
    return vertex_normals_[local_.triangles[triangle][vertex_index(feature)]];
  }
  if (is_edge(feature)) {
    const std::uint32_t edge = edge_of_slot_[3 * triangle + edge_index(feature)];
    return edge == kNoEdge ? Vec3(0, 0, 0) : edge_normals_[edge];
  }
  return face_normals_[triangle];
}

}  // namespace ncv
