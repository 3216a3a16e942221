// The closest triangles of a group of nearby queries, found together: the distance step's
// samples come triangle by triangle, neighbour after neighbour, so a run of them shares most
// of the triangles that can be nearest to any of them. The group's box is searched once,
// shell by shell over the background grid as one query is (closest_point_search.hpp), and
// every candidate triangle is measured against all the group's points at once, a vector of
// points a kernel call (closest_point_lanes.hpp: 2, 4 or 8 lanes, as the CPU offers).
//
// Exact, and bit-identical to brute force, for every point of the group. The argument is the
// single query's with the group box B in place of the point. Each point p's bound is
// bound(p) = best(p) + margin, and the group's bound U the largest of them (bounds only
// shrink). A triangle is left untested for p only when
//  - it lies in no cell the shells visited: those are every cell meeting B whose gap to B was
//    within U when its shell was gathered, and the search stops once the part of the grid
//    not visited is farther than U from B; so the triangle is farther than U >= bound(p)
//    from every point of B (the cells' bounds are exact, the builder lists a triangle in
//    every cell it touches);
//  - or its box is farther than the bound from B, or from the box of p's vector of points
//    (float gaps rounded so that they never exceed the exact ones by more than the slack
//    box_lanes.hpp proves, doubles to a few ulps, both far inside the margin), and the box
//    holds the triangle.
// Either way its true distance to p exceeds bound(p), so the kernel's value for it is above
// best(p) by more than the kernel's rounding: it can neither win nor tie. Every triangle that
// can is measured with the one kernel brute force uses, and ties go to the lower index (the
// lanes compare as `improves` does), so each point gets brute force's hit.
//
// The first group of a run, which has no previous group to take triangles from, starts from
// one point's own search (SampleSearcher); later groups start from the previous group's
// nearest triangles. forget() drops them: the distance step does so at its fixed blocks, so
// the work, and the counters, do not depend on how the blocks are spread over threads.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>

#include "search/closest_point_search.hpp"
#include "search/sample_searcher.hpp"
#include "search/search_index.hpp"

namespace ncv {

// Queries measured together (at most): two, four or eight vectors of points.
inline constexpr std::size_t kGroupSize = 16;

class GroupSearcher {
 public:
  // `index` must outlive this.
  explicit GroupSearcher(const SearchIndex& index);
  ~GroupSearcher();
  GroupSearcher(GroupSearcher&&) noexcept;

  // Measures the first queries (at least one, at most kGroupSize: as many as lie close
  // together) and returns how many: hits[k] = the closest hit of queries[k]. The points are
  // in the frame of the index's triangles; hits holds at least min(kGroupSize, queries.size()).
  std::size_t closest(std::span<const Vec3> queries, std::span<ClosestHit> hits,
                      SearchCounters& counters);
  // The next group starts afresh (from one point's own search).
  void forget();
  // The most a group spans across.
  double reach() const;

  struct State;

 private:
  std::unique_ptr<State> state_;
  // The search compiled for the widest vectors the CPU has (group_search_state.hpp).
  std::size_t (*search_)(State&, std::span<const Vec3>, std::span<ClosestHit>, SearchCounters&);
};

}  // namespace ncv
