#include "search/sample_searcher.hpp"

#include <cmath>

namespace ncv {

SampleSearcher::SampleSearcher(const SearchIndex& index)
    : fine_(index), far_from_(kFarFromCells * index.grid().cell_size) {
  if (index.has_coarse_level()) coarse_.emplace(index, GridLevel::coarse);
}

ClosestHit SampleSearcher::closest(Vec3 q, SearchCounters& counters) {
  GridSearcher& search = coarse_ && previous_ > far_from_ ? *coarse_ : fine_;
  if (hint_ == kNoTriangle) {
    search.forget_hint();
  } else {
    search.set_hint(hint_);
  }
  const ClosestHit hit = search.closest(q, counters);
  hint_ = hit.triangle;
  previous_ = std::sqrt(hit.squared_distance);
  return hit;
}

}  // namespace ncv
