// Distances between generated surfaces for the generator tests, measured with ncverify's own
// exact closest-point search (the search that is bit-identical to brute force).
#pragma once

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "mesh/mesh.hpp"
#include "search/closest_point_search.hpp"
#include "search/indexed_reference.hpp"
#include "search/search_index.hpp"

namespace ncv::gen::test {

// The largest distance from any of `points` to the surface of `mesh`, which may be open (a
// height field's top alone: the warning that it is not a solid is kept out of the test log).
inline double largest_distance(const std::vector<ncv::Vec3>& points, const ncv::Mesh& mesh) {
  const spdlog::level::level_enum level = spdlog::get_level();
  spdlog::set_level(spdlog::level::err);
  const ncv::IndexedReference reference = ncv::index_reference(mesh, "test mesh");
  spdlog::set_level(level);
  const ncv::SearchIndex index(reference);
  ncv::GridSearcher searcher(index);
  ncv::SearchCounters counters;
  double largest = 0;
  for (const ncv::Vec3& p : points) {
    const ncv::ClosestHit hit = searcher.closest(reference.surface->to_local(p), counters);
    largest = std::max(largest, std::sqrt(hit.squared_distance));
  }
  return largest;
}

// Points that stand for a mesh's surface: its vertices and its triangles' centroids.
inline std::vector<ncv::Vec3> surface_points(const ncv::Mesh& mesh) {
  std::vector<ncv::Vec3> points = mesh.vertices;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    points.push_back((mesh.corner(t, 0) + mesh.corner(t, 1) + mesh.corner(t, 2)) / 3.0);
  }
  return points;
}

// The larger of the two one-sided distances between the surfaces, at those points.
inline double two_sided_distance(const ncv::Mesh& a, const ncv::Mesh& b) {
  return std::max(largest_distance(surface_points(a), b), largest_distance(surface_points(b), a));
}

}  // namespace ncv::gen::test
