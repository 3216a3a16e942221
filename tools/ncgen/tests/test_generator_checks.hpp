// Solid checks for the generator tests, computed here independently of the generator: edge
// pairing (closed, consistently oriented, edge-manifold), vertex fans (vertex-manifold),
// Euler characteristic and signed volume.
#pragma once

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "mesh/mesh.hpp"

namespace ncv::gen::test {

struct SolidReport {
  std::size_t unpaired_edges = 0;         // directed edges whose reverse is missing
  std::size_t repeated_edges = 0;         // directed edges used by two triangles
  std::size_t non_manifold_vertices = 0;  // vertices whose triangles are not one fan
  std::size_t degenerate_triangles = 0;   // repeated corner or zero area
  long euler = 0;                         // V - E + F
  double volume = 0;                      // positive when outward-oriented
};

inline std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return (static_cast<std::uint64_t>(a) << 32) | b;
}

// A closed oriented manifold has, around each vertex, opposite edges forming a single cycle.
inline bool single_fan(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& link) {
  std::unordered_map<std::uint32_t, std::uint32_t> next;
  for (const auto& [from, to] : link) {
    if (!next.emplace(from, to).second) return false;
  }
  std::uint32_t at = link.front().first;
  for (std::size_t steps = 1; steps <= link.size(); ++steps) {
    const auto it = next.find(at);
    if (it == next.end()) return false;
    at = it->second;
    if (at == link.front().first) return steps == link.size();
  }
  return false;
}

inline SolidReport check_solid(const ncv::Mesh& mesh) {
  SolidReport report;
  std::unordered_map<std::uint64_t, int> directed;
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> links(mesh.vertex_count());
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const auto& tri = mesh.triangles[t];
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2] || triangle_area(mesh, t) <= 0) {
      ++report.degenerate_triangles;
    }
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = tri[k];
      const std::uint32_t b = tri[(k + 1) % 3];
      const std::uint32_t c = tri[(k + 2) % 3];
      ++directed[edge_key(a, b)];
      links[a].emplace_back(b, c);
    }
    const Vec3 a = mesh.corner(t, 0);
    report.volume += dot(a, cross(mesh.corner(t, 1), mesh.corner(t, 2))) / 6;
  }
  std::unordered_set<std::uint64_t> undirected;
  for (const auto& [key, count] : directed) {
    const auto a = static_cast<std::uint32_t>(key >> 32);
    const auto b = static_cast<std::uint32_t>(key);
    if (count > 1) ++report.repeated_edges;
    if (!directed.contains(edge_key(b, a))) ++report.unpaired_edges;
    undirected.insert(edge_key(std::min(a, b), std::max(a, b)));
  }
  long used_vertices = 0;
  for (const auto& link : links) {
    if (link.empty()) continue;
    ++used_vertices;
    if (!single_fan(link)) ++report.non_manifold_vertices;
  }
  report.euler = used_vertices - static_cast<long>(undirected.size()) +
                 static_cast<long>(mesh.triangle_count());
  return report;
}

// A closed, outward-oriented 2-manifold of sphere topology.
inline bool is_sound_solid(const SolidReport& report) {
  return report.unpaired_edges == 0 && report.repeated_edges == 0 &&
         report.non_manifold_vertices == 0 && report.degenerate_triangles == 0 &&
         report.euler == 2 && report.volume > 0;
}

}  // namespace ncv::gen::test
