#include "search/group_search.hpp"

#include "search/group_search_state.hpp"

#include <cmath>

namespace ncv {
namespace {

// The coarse level serves a group whose start bound reaches farther than this many fine
// cells (the single query's rule, sample_searcher.hpp).
constexpr double kFarFromCells = 0.125;
// A group spans at most this many fine cells across. Measured (one thread, the whole
// distance step, ns a sample; finishing, roughing, the shuffled far finishing part, the
// decimated roughing part): no limit 87.7 / 147 / 513 / -, 2 cells 79.1 / 126 / 106 / -, 1 cell
// 77.7 / 118 / 105 / 127, half a cell 81.7 / 132 / 121 / - (docs/PERFORMANCE.md).
constexpr double kGroupReachCells = 1.0;

GroupSearch widest_group_search() {
  static const GroupSearch widest = group_searches_for_cpu().front().search;
  return widest;
}

}  // namespace

GroupLevel::GroupLevel(const BackgroundGrid& g, std::span<const BoxBlock> b) : grid(&g), boxes(b) {
  const BoundingBox box = g.bounds();
  scale = std::max(max_abs(box.min), max_abs(box.max));
  for (int axis = 0; axis < 3; ++axis) {
    origin[axis] = g.origin[axis];
    box_min[axis] = box.min[axis];
    box_max[axis] = box.max[axis];
    last_cell[axis] = std::int64_t{g.dims[axis]} - 1;
  }
  inverse_cell = 1.0 / g.cell_size;
}

GroupSearcher::State::State(const SearchIndex& index)
    : triangles(index.triangles()),
      fine(index.grid(), index.boxes()),
      far_from(kFarFromCells * index.grid().cell_size),
      single(index),
      stamps(index.triangles().size(), 0) {
  if (index.has_coarse_level()) {
    coarse = GroupLevel(index.grid(GridLevel::coarse), index.boxes(GridLevel::coarse));
    has_coarse = true;
  }
  candidates.reserve(256);
  const double reach = kGroupReachCells * index.grid().cell_size;
  reach_sq = reach * reach;
}

std::vector<GroupSearchBuild> group_searches_for_cpu() {
  std::vector<GroupSearchBuild> builds;
#if defined(__x86_64__) && defined(__GNUC__)
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
      __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw")) {
    builds.push_back({"avx512", search_group_avx512});
  }
  if (__builtin_cpu_supports("avx2")) builds.push_back({"avx2", search_group_avx2});
#endif
  builds.push_back({"sse2", search_group_sse2});
  return builds;
}

GroupSearcher::GroupSearcher(const SearchIndex& index)
    : state_(std::make_unique<State>(index)), search_(widest_group_search()) {}
GroupSearcher::~GroupSearcher() = default;
GroupSearcher::GroupSearcher(GroupSearcher&&) noexcept = default;

std::size_t GroupSearcher::closest(std::span<const Vec3> queries, std::span<ClosestHit> hits,
                                   SearchCounters& counters) {
  return search_(*state_, queries, hits, counters);
}

double GroupSearcher::reach() const {
  return std::sqrt(state_->reach_sq);
}

void GroupSearcher::forget() {
  state_->forget();
}

}  // namespace ncv
