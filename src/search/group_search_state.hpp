// What a GroupSearcher keeps between groups, and its search compiled once per instruction
// set (group_search_lanes.hpp, built by group_search_sse2.cpp, group_search_avx2.cpp and
// group_search_avx512.cpp); group_search.cpp chooses one for the CPU it runs on.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "search/group_search.hpp"

namespace ncv {

// One level of the grid as the group search reads it.
struct GroupLevel {
  const BackgroundGrid* grid = nullptr;
  std::span<const BoxBlock> boxes;
  std::array<double, 3> origin{}, box_min{}, box_max{};
  std::array<std::int64_t, 3> last_cell{};
  double inverse_cell = 0;
  double scale = 0;  // coordinate scale of the grid box

  GroupLevel() = default;
  GroupLevel(const BackgroundGrid& g, std::span<const BoxBlock> b);
};

// A triangle found in a visited cell, with its box's squared float gap to the group's box.
struct GroupCandidate {
  float squared;
  std::uint32_t triangle;
};

// Triangles a group starts from: the distinct nearest ones of the group before.
inline constexpr std::size_t kGroupSeeds = 4;

struct GroupSearcher::State {
  explicit State(const SearchIndex& index);

  // The next group starts afresh (GroupSearcher::forget).
  void forget() {
    seed_count = 0;
    single.forget();
  }

  // A fresh stamp for a group: a triangle is measured at most once per group.
  void next_epoch() {
    if (++epoch == 0) {
      std::fill(stamps.begin(), stamps.end(), 0);
      epoch = 1;
    }
  }

  MeshCorners triangles;
  GroupLevel fine, coarse;
  bool has_coarse = false;
  double far_from;        // a group whose start bound reaches farther uses the coarse level
  SampleSearcher single;  // the first point of a run, which has no seeds
  std::vector<std::uint32_t> stamps;
  std::uint32_t epoch = 0;
  std::array<std::uint32_t, kGroupSeeds> seeds{};
  std::size_t seed_count = 0;
  std::vector<GroupCandidate> candidates;
  double reach_sq;  // the most a group spans across, squared
};

// The search of one group (group_search.hpp's closest), for 2, 4 and 8 lanes; the last two
// only where the CPU has AVX2, and AVX-512 F, VL, DQ and BW.
using GroupSearch = std::size_t (*)(GroupSearcher::State&, std::span<const Vec3>,
                                    std::span<ClosestHit>, SearchCounters&);
std::size_t search_group_sse2(GroupSearcher::State& state, std::span<const Vec3> queries,
                              std::span<ClosestHit> hits, SearchCounters& counters);
std::size_t search_group_avx2(GroupSearcher::State& state, std::span<const Vec3> queries,
                              std::span<ClosestHit> hits, SearchCounters& counters);
std::size_t search_group_avx512(GroupSearcher::State& state, std::span<const Vec3> queries,
                                std::span<ClosestHit> hits, SearchCounters& counters);

struct GroupSearchBuild {
  const char* name;  // the instruction set
  GroupSearch search;
};
// The builds this CPU runs, widest first: GroupSearcher takes the first.
std::vector<GroupSearchBuild> group_searches_for_cpu();

}  // namespace ncv
