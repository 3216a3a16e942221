// The search a run of consecutive queries makes (the distance step's samples, certification's
// points): each starts with the previous query's closest triangle as its hint, over the
// grid, or over the coarse level (coarse_grid.hpp) when the previous query lay farther from
// the reference than an eighth of a grid cell: its ball then likely leaves its cell, and meets
// fewer coarse cells. Both levels give the exact result (closest_point_search.hpp), so the
// choice changes the work only, and it depends on the queries alone.
//
// Roughing (1.9 mm cells, samples up to 6 mm off the nominal): the distance step 0.287 ->
// 0.236 s on one thread (an eighth of a cell), 0.251 s (a quarter), 0.245 s (always coarse);
// the finishing parts the same within the noise from an eighth up, 10 % slower always coarse.
#pragma once

#include <optional>

#include "search/closest_point_search.hpp"
#include "search/search_index.hpp"

namespace ncv {

class SampleSearcher {
 public:
  // `index` must outlive this.
  explicit SampleSearcher(const SearchIndex& index);

  ClosestHit closest(Vec3 q, SearchCounters& counters);
  // The next query starts with triangle t (or without a hint: kNoTriangle).
  void set_hint(std::uint32_t t) { hint_ = t; }
  // The next query starts afresh: no hint, the grid's own level.
  void forget() {
    hint_ = kNoTriangle;
    previous_squared_ = 0;
  }

 private:
  GridSearcher fine_;
  std::optional<GridSearcher> coarse_;
  double far_from_squared_;
  std::uint32_t hint_ = kNoTriangle;
  double previous_squared_ = 0;  // the previous query's squared distance
};

}  // namespace ncv
