// Signed distances to the nominal (paper §3.2, docs/METHOD.md "Signed distance"): for every
// query point, the exact distance to the nearest nominal triangle, signed positive outside
// the nominal solid (excess material) and negative inside (gouge), with the closest point
// and face.
//
// The search runs over the background grid, or over every triangle when no grid is given;
// both return bit-identical results (see closest_point_search.hpp). A point exactly on the
// nominal gets +0.0 whatever the sign method.
//
// Sign methods (sign_method.hpp):
//   pseudonormal  sign of (p - c) . n, n the pseudonormal of the feature c lies on (face,
//                 edge or vertex). Where n is zero (a feature whose faces cancel or are
//                 all degenerate), the exact winding number decides for that point; where
//                 only the product is zero, the point is on the surface up to rounding
//                 and counts as outside (+).
//   winding       inside when the generalized winding number w(p) >= 0.5, evaluated with
//                 the fast hierarchy (WindingNumberTree, built once per call).
//   paper         the sample's own normal N_p: positive when N_p . (p - c) > 0.
//   automatic     the nominal's choice (ReferenceSurface::automatic_sign_method).
//
// Parallel over fixed blocks of points with oneTBB. Every value of a point is computed on its own
// and the statistics are integer sums, so the output does not depend on the thread count.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "distance/side_rule.hpp"
#include "reference/reference_surface.hpp"
#include "reference/sign_method.hpp"
#include "search/search_index.hpp"
#include "util/buffer.hpp"

namespace ncv {

// Points are measured in fixed blocks of this many (the last one shorter); each block starts
// without a search hint, so the counters do not depend on the thread count.
inline constexpr std::size_t kDistanceBlockSize = 512;

// Buffers: filled by the parallel loop without a serial zeroing pass first (buffer.hpp).
struct DistanceField {
  Buffer<double> distance;  // signed
  Buffer<std::uint32_t> closest_face;
};

struct SearchStatistics {
  std::uint64_t queries = 0;
  std::uint64_t triangles_tested = 0;      // exact tests: the paper's Table 2 statistic, summed
  std::uint64_t triangles_considered = 0;  // cell-list entries box-checked, + the hints
  std::uint64_t cells_visited = 0;         // 0 for brute force

  double triangles_per_query() const {
    return queries ? static_cast<double>(triangles_tested) / static_cast<double>(queries) : 0.0;
  }
};

// Called from the calling thread only, after each block of points it finished.
using DistanceProgress = std::function<void(std::size_t done, std::size_t total)>;

// The method `requested` stands for on this nominal: automatic resolves to the nominal's
// choice, the others to themselves.
SignMethod resolve_sign_method(const ReferenceSurface& nominal, SignMethod requested);

// `points` in the global frame, each finite and within kMaxCoordinate (InputError
// otherwise, naming "query points"). `sample_normals` is read only by SignMethod::paper
// and must then hold one normal per point (UsageError otherwise).
//
// Over the background grid of the index's reference:
DistanceField compute_signed_distances(const SearchIndex& index, std::span<const Vec3> points,
                                       std::span<const Vec3> sample_normals, SignMethod method,
                                       SearchStatistics* statistics = nullptr,
                                       const DistanceProgress& progress = {});
// By brute force, every triangle of the surface for every point (the reference result):
DistanceField compute_signed_distances(const ReferenceSurface& surface,
                                       std::span<const Vec3> points,
                                       std::span<const Vec3> sample_normals, SignMethod method,
                                       SearchStatistics* statistics = nullptr,
                                       const DistanceProgress& progress = {});
// The same two with a side rule made already (a resolved method on the same surface), so
// that a caller signing more points later (certification) builds its winding tree once. Over
// the grid, `order` is the order the last order.size() points are measured in (each of their
// numbers once; sampling/measuring_order.hpp), after the others in theirs: every value is the
// same in any order, only the search's counters change.
DistanceField compute_signed_distances(const SearchIndex& index, std::span<const Vec3> points,
                                       std::span<const Vec3> sample_normals, const SideRule& side,
                                       SearchStatistics* statistics = nullptr,
                                       const DistanceProgress& progress = {},
                                       std::span<const std::uint32_t> order = {});
DistanceField compute_signed_distances(const ReferenceSurface& surface,
                                       std::span<const Vec3> points,
                                       std::span<const Vec3> sample_normals, const SideRule& side,
                                       SearchStatistics* statistics = nullptr,
                                       const DistanceProgress& progress = {});

}  // namespace ncv
