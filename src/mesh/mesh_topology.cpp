#include "mesh/mesh_topology.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <functional>
#include <numeric>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include "util/block_offsets.hpp"
#include "util/bucket_positions.hpp"
#include "util/buffer.hpp"
#include "util/ordered_reduce.hpp"
#include "util/parallel_over.hpp"
#include "util/serial_sum.hpp"

namespace ncv {
namespace {

std::uint32_t slot_start(const Mesh& mesh, std::uint32_t slot) {
  return mesh.triangles[slot / 3][slot % 3];
}
std::uint32_t slot_end(const Mesh& mesh, std::uint32_t slot) {
  return mesh.triangles[slot / 3][(slot % 3 + 1) % 3];
}
std::uint32_t slot_low(const Mesh& mesh, std::uint32_t slot) {
  return std::min(slot_start(mesh, slot), slot_end(mesh, slot));
}
std::uint32_t slot_high(const Mesh& mesh, std::uint32_t slot) {
  return std::max(slot_start(mesh, slot), slot_end(mesh, slot));
}

// Slots of usable triangles as keys (higher vertex << 32 | slot), bucketed by lower vertex
// (counting sort keeps slot order). Sorting a bucket's keys orders its slots by higher
// vertex, then by slot, without reading the mesh again. The sort runs on a fixed number of
// chunks of slots side by side (BucketPositions): the keys are the serial sort's whatever the
// threads.
constexpr std::size_t kSlotChunks = 4;

Buffer<std::uint64_t> slot_keys_by_low_vertex(const Mesh& mesh,
                                              Buffer<std::uint32_t>& bucket_begin) {
  const std::size_t vertices = mesh.vertex_count();
  const std::uint64_t slot_total = 3 * mesh.triangle_count();
  const auto chunk_slots = [&](std::size_t c, auto&& visit) {
    const auto end = static_cast<std::uint32_t>(slot_total * (c + 1) / kSlotChunks);
    for (auto s = static_cast<std::uint32_t>(slot_total * c / kSlotChunks); s < end; ++s) {
      if (!repeats_corner(mesh.triangles[s / 3])) visit(s);
    }
  };
  BucketPositions<std::uint32_t, kSlotChunks> positions(vertices, [&](std::size_t c, auto&& emit) {
    chunk_slots(c, [&](std::uint32_t s) { emit(slot_low(mesh, s)); });
  });
  Buffer<std::uint64_t> keys(positions.starts().back());
  tbb::parallel_for(std::size_t{0}, kSlotChunks, [&](std::size_t c) {
    chunk_slots(c, [&](std::uint32_t s) {
      keys[positions.next(c, slot_low(mesh, s))] = std::uint64_t{slot_high(mesh, s)} << 32 | s;
    });
  });
  bucket_begin = positions.take_starts();
  return keys;
}

// Corners united across two-triangle edges, from several threads at once: a root is linked
// below a smaller root by compare-and-swap (a lost race retries from the new roots), and
// paths are halved by compare-and-swap too, so every link points to a smaller corner and
// each fan ends with its lowest corner as root, in whatever order the unions ran.
class CornerForest {
 public:
  // Each corner its own root, written in parallel into an unwritten buffer (a zero-filled
  // vector and a serial iota were two serial passes over 15 MB on the finishing workpiece).
  explicit CornerForest(std::size_t corners) : parent_(corners) {
    parallel_over(corners, 1 << 16,
                  [&](std::size_t c) { parent_[c] = static_cast<std::uint32_t>(c); });
  }

  std::uint32_t find(std::uint32_t c) {
    for (;;) {
      std::atomic_ref<std::uint32_t> link(parent_[c]);
      std::uint32_t p = link.load(std::memory_order_relaxed);
      if (p == c) return c;
      const std::uint32_t grandparent =
          std::atomic_ref<std::uint32_t>(parent_[p]).load(std::memory_order_relaxed);
      if (grandparent != p) link.compare_exchange_weak(p, grandparent, std::memory_order_relaxed);
      c = grandparent;
    }
  }

  void unite(std::uint32_t a, std::uint32_t b) {
    for (;;) {
      a = find(a);
      b = find(b);
      if (a == b) return;
      if (a < b) std::swap(a, b);
      std::uint32_t root = a;
      if (std::atomic_ref<std::uint32_t>(parent_[a])
              .compare_exchange_strong(root, b, std::memory_order_relaxed)) {
        return;
      }
    }
  }

 private:
  Buffer<std::uint32_t> parent_;
};

std::uint32_t start_corner(std::uint32_t slot) {
  return slot;
}
std::uint32_t end_corner(std::uint32_t slot) {
  return slot / 3 * 3 + (slot % 3 + 1) % 3;
}

// A vertex is non-manifold when its triangles form more than one fan, fans being joined
// across the two-triangle edges around it: corners are united across each such edge and
// every vertex counts its distinct roots (its second one makes it non-manifold). Both passes
// run in parallel; the serial union-find took 0.04-0.05 s of the 1.25 M-triangle workpiece's
// topology.
std::uint64_t count_non_manifold_vertices(const Mesh& mesh, const EdgeIncidence& incidence) {
  CornerForest forest(3 * mesh.triangle_count());
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, incidence.edge_count(), 1 << 14), [&](const auto& r) {
        for (std::size_t e = r.begin(); e != r.end(); ++e) {
          if (incidence.slot_count(e) != 2) continue;
          const std::uint32_t s1 = incidence.slots[incidence.edge_begin[e]];
          const std::uint32_t s2 = incidence.slots[incidence.edge_begin[e] + 1];
          const bool same_direction = slot_start(mesh, s1) == slot_start(mesh, s2);
          forest.unite(start_corner(s1), same_direction ? start_corner(s2) : end_corner(s2));
          forest.unite(end_corner(s1), same_direction ? end_corner(s2) : start_corner(s2));
        }
      });
  std::vector<std::uint8_t> fans(mesh.vertex_count(), 0);  // 0, 1, or 2 for two and more
  return tbb::parallel_reduce(
      tbb::blocked_range<std::uint32_t>(0, static_cast<std::uint32_t>(3 * mesh.triangle_count()),
                                        1 << 14),
      std::uint64_t{0},
      [&](const auto& r, std::uint64_t non_manifold) {
        for (std::uint32_t c = r.begin(); c != r.end(); ++c) {
          if (repeats_corner(mesh.triangles[c / 3]) || forest.find(c) != c) continue;
          std::atomic_ref<std::uint8_t> count(fans[mesh.triangles[c / 3][c % 3]]);
          std::uint8_t seen = count.load(std::memory_order_relaxed);
          while (seen < 2 && !count.compare_exchange_weak(seen, static_cast<std::uint8_t>(seen + 1),
                                                          std::memory_order_relaxed)) {
          }
          non_manifold += seen == 1 ? 1 : 0;
        }
        return non_manifold;
      },
      std::plus<>());
}

struct EdgeKinds {
  std::uint64_t boundary = 0, non_manifold = 0, misoriented = 0;
};

// Blocks of the parallel counts below (ordered_reduce: fixed blocks, any thread count).
constexpr std::size_t kCountBlock = 1 << 14;

void count_edge_kinds(const Mesh& mesh, const EdgeIncidence& incidence, TopologyReport& report) {
  report.edges = incidence.edge_count();
  const EdgeKinds kinds = ordered_reduce(
      incidence.edge_count(), kCountBlock, EdgeKinds{},
      [&](std::size_t begin, std::size_t end) {
        EdgeKinds part;
        for (std::size_t e = begin; e < end; ++e) {
          const std::uint32_t count = incidence.slot_count(e);
          part.boundary += count == 1;
          part.non_manifold += count > 2;
          std::uint32_t forward = 0;
          for (std::uint32_t i = incidence.edge_begin[e]; i < incidence.edge_begin[e + 1]; ++i) {
            const std::uint32_t s = incidence.slots[i];
            forward += slot_start(mesh, s) < slot_end(mesh, s);
          }
          part.misoriented += count >= 2 && 2 * forward != count;
        }
        return part;
      },
      [](EdgeKinds& acc, const EdgeKinds& part) {
        acc.boundary += part.boundary;
        acc.non_manifold += part.non_manifold;
        acc.misoriented += part.misoriented;
      });
  report.boundary_edges = kinds.boundary;
  report.non_manifold_edges = kinds.non_manifold;
  report.misoriented_edges = kinds.misoriented;
}

std::uint64_t count_degenerate(const Mesh& mesh) {
  return ordered_reduce(
      mesh.triangle_count(), kCountBlock, std::uint64_t{0},
      [&](std::size_t begin, std::size_t end) {
        std::uint64_t part = 0;
        for (std::size_t t = begin; t < end; ++t) {
          part += repeats_corner(mesh.triangles[t]) ||
                  is_degenerate_triangle(mesh.corner(t, 0), mesh.corner(t, 1), mesh.corner(t, 2));
        }
        return part;
      },
      [](std::uint64_t& acc, std::uint64_t part) { acc += part; });
}

std::array<std::uint32_t, 3> sorted_corners(const Triangle& t) {
  std::array<std::uint32_t, 3> v = t;
  std::sort(v.begin(), v.end());
  return v;
}

// The corner of the slot's triangle that is not on the slot's edge.
std::uint32_t opposite_corner(const Mesh& mesh, std::uint32_t slot) {
  return mesh.triangles[slot / 3][(slot % 3 + 2) % 3];
}

// Triangles with the same three vertices as an earlier one. Two such triangles without a
// repeated corner share all three edges, so they meet in the slot list of the edge between
// their two lowest vertices, the one whose opposite corner is the highest: there, each such
// slot counts when an earlier one has the same opposite corner (a few slots an edge, two on
// a closed mesh; sorting every triangle instead made the topology of the 1.25 M-triangle
// finishing workpieces 0.13-0.2 s, not 0.08-0.13, on 2 threads). The rare triangles with a
// repeated corner, which have no edges, are sorted apart.
std::uint64_t count_duplicates(const Mesh& mesh, const EdgeIncidence& incidence) {
  const std::uint64_t with_edges = ordered_reduce(
      incidence.edge_count(), kCountBlock, std::uint64_t{0},
      [&](std::size_t begin, std::size_t end) {
        std::uint64_t part = 0;
        std::vector<std::uint32_t> opposite;  // of the slots on their triangle's lowest edge
        for (std::size_t e = begin; e < end; ++e) {
          const std::uint32_t first = incidence.edge_begin[e], last = incidence.edge_begin[e + 1];
          if (last - first < 2) continue;
          const std::uint32_t high = slot_high(mesh, incidence.slots[first]);
          if (last - first == 2) {
            const std::uint32_t a = opposite_corner(mesh, incidence.slots[first]);
            part += a > high && a == opposite_corner(mesh, incidence.slots[first + 1]);
            continue;
          }
          opposite.clear();
          for (std::uint32_t i = first; i < last; ++i) {
            const std::uint32_t c = opposite_corner(mesh, incidence.slots[i]);
            if (c > high) opposite.push_back(c);
          }
          std::sort(opposite.begin(), opposite.end());
          for (std::size_t i = 1; i < opposite.size(); ++i) part += opposite[i] == opposite[i - 1];
        }
        return part;
      },
      [](std::uint64_t& acc, std::uint64_t part) { acc += part; });
  std::vector<std::array<std::uint32_t, 3>> repeating;
  for (const Triangle& t : mesh.triangles) {
    if (repeats_corner(t)) repeating.push_back(sorted_corners(t));
  }
  std::sort(repeating.begin(), repeating.end());
  std::uint64_t duplicates = with_edges;
  for (std::size_t i = 1; i < repeating.size(); ++i) duplicates += repeating[i] == repeating[i - 1];
  return duplicates;
}

// Relative to the bounding-box centre, so a part far from the origin loses no digits.
double signed_volume(const Mesh& mesh) {
  const Vec3 centre = bounding_box(mesh).center();
  const double six_volume = serial_sum(mesh.triangle_count(), [&](std::size_t t) {
    const Vec3 a = mesh.corner(t, 0) - centre;
    return dot(a, cross(mesh.corner(t, 1) - centre, mesh.corner(t, 2) - centre));
  });
  return six_volume / 6;
}

}  // namespace

bool is_degenerate_triangle(Vec3 a, Vec3 b, Vec3 c) {
  const double longest_sq =
      std::max({squared_norm(b - a), squared_norm(c - b), squared_norm(a - c)});
  return norm(cross(b - a, c - a)) <= 1e-10 * longest_sq;
}

// Each vertex's bucket is sorted by high vertex and its runs (edges) counted in parallel;
// the edges are then numbered bucket after bucket, as a serial pass would number them.
EdgeIncidence build_edge_incidence(const Mesh& mesh) {
  Buffer<std::uint32_t> bucket_begin;
  Buffer<std::uint64_t> keys = slot_keys_by_low_vertex(mesh, bucket_begin);
  const auto starts_edge = [&](std::uint32_t i, std::size_t v) {
    return i == bucket_begin[v] || keys[i] >> 32 != keys[i - 1] >> 32;
  };
  const std::size_t vertices = mesh.vertex_count();
  // Bucket v's edge count at v + 1; after the prefix sum, bucket v's first edge at v and the
  // total last.
  std::vector<std::uint32_t> first_edge(vertices + 1, 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vertices, 1 << 12),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t v = range.begin(); v != range.end(); ++v) {
                        std::sort(keys.begin() + bucket_begin[v],
                                  keys.begin() + bucket_begin[v + 1]);
                        std::uint32_t edges = 0;
                        for (std::uint32_t i = bucket_begin[v]; i < bucket_begin[v + 1]; ++i) {
                          edges += starts_edge(i, v);
                        }
                        first_edge[v + 1] = edges;
                      }
                    });
  std::partial_sum(first_edge.begin(), first_edge.end(), first_edge.begin());

  EdgeIncidence incidence;
  incidence.edge_of_slot.resize(3 * mesh.triangle_count());
  incidence.edge_begin.resize(first_edge.back() + 1);
  incidence.edge_begin.back() = static_cast<std::uint32_t>(keys.size());
  incidence.slots.resize(keys.size());
  // The slots of triangles that repeat a corner have no edge; every other slot gets its
  // edge below.
  parallel_over(mesh.triangle_count(), 1 << 14, [&](std::size_t t) {
    if (!repeats_corner(mesh.triangles[t])) return;
    for (std::size_t k = 0; k < 3; ++k) incidence.edge_of_slot[3 * t + k] = kNoEdge;
  });
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vertices, 1 << 12),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t v = range.begin(); v != range.end(); ++v) {
                        std::uint32_t next = first_edge[v];  // the next edge to start
                        for (std::uint32_t i = bucket_begin[v]; i < bucket_begin[v + 1]; ++i) {
                          if (starts_edge(i, v)) incidence.edge_begin[next++] = i;
                          const auto slot = static_cast<std::uint32_t>(keys[i]);
                          incidence.slots[i] = slot;
                          incidence.edge_of_slot[slot] = next - 1;
                        }
                      }
                    });
  return incidence;
}

TopologyReport analyse_topology(const Mesh& mesh, const EdgeIncidence& incidence) {
  TopologyReport report;
  report.triangles = mesh.triangle_count();
  count_edge_kinds(mesh, incidence, report);
  report.non_manifold_vertices = count_non_manifold_vertices(mesh, incidence);
  report.degenerate_triangles = count_degenerate(mesh);
  report.duplicate_triangles = count_duplicates(mesh, incidence);
  report.signed_volume = signed_volume(mesh);
  return report;
}

}  // namespace ncv
