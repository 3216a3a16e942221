#include "search/sample_searcher.hpp"

namespace ncv {
namespace {

// How far, in grid cells, the previous query must lie for the coarse level (the header).
constexpr double kFarFromCells = 0.125;

}  // namespace

SampleSearcher::SampleSearcher(const SearchIndex& index) : fine_(index) {
  const double far_from = kFarFromCells * index.grid().cell_size;
  far_from_squared_ = far_from * far_from;
  if (index.has_coarse_level()) coarse_.emplace(index, GridLevel::coarse);
}

ClosestHit SampleSearcher::closest(Vec3 q, SearchCounters& counters) {
  GridSearcher& search = coarse_ && previous_squared_ > far_from_squared_ ? *coarse_ : fine_;
  search.set_hint(hint_);
  const ClosestHit hit = search.closest(q, counters);
  hint_ = hit.triangle;
  previous_squared_ = hit.squared_distance;
  return hit;
}

}  // namespace ncv
