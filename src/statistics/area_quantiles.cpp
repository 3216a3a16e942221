#include "statistics/area_quantiles.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include "statistics/patch_passes.hpp"
#include "statistics/rank_selection.hpp"
#include "util/buffer.hpp"

namespace ncv {

namespace {

// Split points per refinement step: each step leaves at most 1/kSplits of the corner
// values inside the bracket, so a few steps reach a bracket free of them.
constexpr std::size_t kSplits = 32;

// A first bracket holds about 1/kSplits of the corner values, each a corner of a few
// patches (six inside a lattice): its partial patches are reserved at this many a value, so
// that they are gathered without the buffer growing. Growing doubled it from empty, a fresh
// block each time, whose pages the host clears (docs/PERFORMANCE.md); a reserve's unwritten
// pages cost nothing, and a large one takes a freed buffer kept with its pages backed
// (util/buffer.hpp). Finishing part, 1.8 M samples: 20-163 k patches a bracket, 1.8 a value.
constexpr std::size_t kPartialPerValue = 4;

// std::lower_bound over the few split points without a branch to mispredict: the patches'
// corner values fall anywhere among them.
std::size_t lower_bound_index(const std::vector<double>& splits, double x) {
  const double* base = splits.data();
  std::size_t length = splits.size();
  while (length > 1) {
    const std::size_t half = length / 2;
    base = base[half - 1] < x ? base + half : base;
    length -= half;
  }
  return static_cast<std::size_t>(base - splits.data()) + (length == 1 && *base < x ? 1 : 0);
}

// GCC's vector extension, kLanes doubles (its attribute takes no template argument).
template <int kLanes>
struct LanesOf;
template <>
struct LanesOf<2> {
  typedef double type __attribute__((vector_size(16)));
};
template <>
struct LanesOf<4> {
  typedef double type __attribute__((vector_size(32)));
};

// sums[j] += area_at_most(p, splits[j]) for the splits [j, end), all inside [lo, hi):
// kLanes at a time, then fewer, each lane the closed form's own operations in its order (so
// the same bits), both branches computed and the one area_strictly_inside takes selected
// (the other lane's quotients may divide by zero; they are dropped). Where most corner
// values are rounding noise around zero (a part on its nominal), the first splits all fall
// within the noise and every patch across it spans them all: two divisions a split were
// most of this pass.
template <int kLanes>
[[gnu::always_inline]] inline void add_areas_inside(const LinearPatch& p, const double* splits,
                                                    std::size_t j, std::size_t end, double* sums) {
  if constexpr (kLanes == 1) {
    if (j < end) sums[j] += area_strictly_inside(p, splits[j]);
  } else {
    using Lanes = typename LanesOf<kLanes>::type;
    for (; j + kLanes <= end; j += kLanes) {
      Lanes t;
      for (int k = 0; k < kLanes; ++k) t[k] = splits[j + k];
      const Lanes rise = t - p.lo, fall = p.hi - t;
      const Lanes up = p.area * (rise / (p.mid - p.lo)) * (rise / (p.hi - p.lo));
      const Lanes down = p.area - p.area * (fall / (p.hi - p.lo)) * (fall / (p.hi - p.mid));
      const Lanes area = t < p.mid ? up : down;
      for (int k = 0; k < kLanes; ++k) sums[j + k] += area[k];
    }
    add_areas_inside<kLanes / 2>(p, splits, j, end, sums);
  }
}

// One block's share of the distribution function at each split point (ascending): [0, m)
// the patches straddling a split, [m, 2m] the whole areas of those wholly at or below one,
// by the first split at or above them.
using SplitSums = std::vector<double>;

template <int kLanes>
[[gnu::always_inline]] inline SplitSums split_sums_by(std::span<const LinearPatch> patches,
                                                      const std::vector<double>& splits) {
  const std::size_t m = splits.size();
  SplitSums part(2 * m + 1, 0.0);
  // Neighbouring patches mostly lie between the same two splits, (low, high]: then both
  // searches would give `last` and the patch adds its whole area there.
  // That sum is kept in a register meanwhile, each add the one it was (through memory each
  // waited for the store before it).
  std::size_t last = 0;
  double in_last = 0;
  double low = -std::numeric_limits<double>::infinity(), high = low;
  for (const LinearPatch& p : patches) {
    if (low < p.lo && p.hi <= high) {
      in_last += p.area;
      continue;
    }
    part[m + last] = in_last;
    // The splits in [lo, hi): both ends searched without a branch (a walk from the first
    // mispredicted its exit about once a patch).
    const std::size_t first = lower_bound_index(splits, p.lo);
    const std::size_t whole = lower_bound_index(splits, p.hi);
    add_areas_inside<kLanes>(p, splits.data(), first, whole, part.data());
    last = whole;
    in_last = part[m + last] + p.area;
    low = whole > 0 ? splits[whole - 1] : -std::numeric_limits<double>::infinity();
    high = whole < m ? splits[whole] : std::numeric_limits<double>::infinity();
  }
  part[m + last] = in_last;
  return part;
}

#if defined(__x86_64__) && defined(__GNUC__)
// Four lanes where the CPU has AVX2, two (SSE2, which every x86-64 has) elsewhere: four
// lanes built for SSE2 alone were slower than one. The statistics (profile tool, 2 threads)
// of the finishing part 68 -> 64.5 ms, of the uncut slot 80 -> 75 ms. Without FMA, so that
// no product and sum are fused: the same bits either way.
SplitSums split_sums_sse2(std::span<const LinearPatch> patches, const std::vector<double>& splits) {
  return split_sums_by<2>(patches, splits);
}

[[gnu::target("avx2")]] SplitSums split_sums_avx2(std::span<const LinearPatch> patches,
                                                  const std::vector<double>& splits) {
  return split_sums_by<4>(patches, splits);
}

SplitSums split_sums(std::span<const LinearPatch> patches, const std::vector<double>& splits) {
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2 ? split_sums_avx2(patches, splits) : split_sums_sse2(patches, splits);
}
#else
SplitSums split_sums(std::span<const LinearPatch> patches, const std::vector<double>& splits) {
  return split_sums_by<2>(patches, splits);
}
#endif

void add_split_sums(SplitSums& acc, const SplitSums& part) {
  for (std::size_t k = 0; k < acc.size(); ++k) acc[k] += part[k];
}

// The distribution function at each of the m split points, from the blocks' sums combined.
std::vector<double> at_most_from(const SplitSums& sums, std::size_t m) {
  std::vector<double> at_most(m);
  double whole = 0;
  for (std::size_t j = 0; j < m; ++j) {
    whole += sums[m + j];
    at_most[j] = whole + sums[j];
  }
  return at_most;
}

// Distribution function at each split point (ascending): patches wholly at or below a
// split add their whole area from there on, patches straddling it their closed form.
std::vector<double> area_at_most_each(const PatchSource& patches,
                                      const std::vector<double>& splits) {
  const SplitSums sums = reduce_patch_blocks(
      patches, SplitSums(2 * splits.size() + 1, 0.0),
      [&](std::span<const LinearPatch> block) { return split_sums(block, splits); },
      add_split_sums);
  return at_most_from(sums, splits.size());
}

// Up to kSplits distinct values spread evenly (by rank) over sorted[begin, end).
std::vector<double> rank_splits(std::span<const double> sorted, std::size_t begin,
                                std::size_t end) {
  std::vector<double> splits;
  const std::size_t count = end - begin;
  const std::size_t wanted = std::min(count, kSplits);
  for (std::size_t k = 1; k <= wanted; ++k) {
    const double value = sorted[begin + (count * k) / wanted - 1];
    if (splits.empty() || splits.back() < value) splits.push_back(value);
  }
  return splits;
}

// The distribution function of the patches that span a bracket (a, b) without a corner
// value inside it: each is one quadratic piece there, so their sum is a quadratic in
// u = t - a. Every term stays below the patch area on the bracket, so the sum is as
// well-conditioned as the area itself.
struct Quadratic {
  double c0 = 0, c1 = 0, c2 = 0;

  double operator()(double u) const { return c0 + u * (c1 + u * c2); }

  void add_spanning(const LinearPatch& p, double a, double b) {
    if (p.mid >= b) {  // rising: area (t - lo)^2 / ((mid - lo)(hi - lo))
      const double k = p.area / ((p.mid - p.lo) * (p.hi - p.lo));
      const double r = a - p.lo;
      c0 += k * r * r;
      c1 += 2 * k * r;
      c2 += k;
    } else {  // falling: area - area (hi - t)^2 / ((hi - lo)(hi - mid))
      const double k = p.area / ((p.hi - p.lo) * (p.hi - p.mid));
      const double g = p.hi - a;
      c0 += p.area - k * g * g;
      c1 += 2 * k * g;
      c2 -= k;
    }
  }

  // Re-expresses the polynomial in u' = u - delta.
  void shift(double delta) {
    c0 += delta * (c1 + delta * c2);
    c1 += 2 * delta * c2;
  }
};

// The search state: F(a) < target <= F(b), and for a < t < b
//   F(t) = base + spanning(t - a) + sum over `partial` of area_at_most(p, t),
// base being the area wholly at or below a and `partial` the patches with a corner value
// inside (a, b). Only those need evaluating at split points, and they shrink with the
// number of corner values inside the bracket.
struct Bracket {
  double a = 0, b = 0;
  double base = 0;
  Quadratic spanning;
  Buffer<LinearPatch> partial;
};

void add_to_bracket(Bracket& bracket, const LinearPatch& p) {
  const double a = bracket.a, b = bracket.b;
  if (p.hi <= a) {
    bracket.base += p.area;
  } else if (p.lo >= b) {
    return;
  } else if (p.lo <= a && p.hi >= b && (p.mid <= a || p.mid >= b)) {
    bracket.spanning.add_spanning(p, a, b);
  } else {
    bracket.partial.push_back(p);
  }
}

// Narrows the bracket to (a, b) within it; patches are all patches on the first step,
// then those the bracket held as partial.
void narrow(Bracket& bracket, std::span<const LinearPatch> patches, double a, double b) {
  bracket.spanning.shift(a - bracket.a);
  bracket.a = a;
  bracket.b = b;
  bracket.partial.clear();
  for (const LinearPatch& p : patches) add_to_bracket(bracket, p);
}

// The first narrowing of up to N fresh brackets, continued over the next range of patches:
// what narrow() does for each, in the same patch order, so every sum is narrow()'s to the
// bit. Most patches lie wholly below or above a bracket; the bases, kept in registers over
// the range, take the area of those below without a branch (adding +0.0 leaves a sum of
// areas as it is).
template <std::size_t N>
void narrow_together(std::span<Bracket> brackets, std::span<const LinearPatch> patches) {
  std::array<double, N> a{}, b{}, base{};
  for (std::size_t k = 0; k < N; ++k) {
    a[k] = brackets[k].a;
    b[k] = brackets[k].b;
    base[k] = brackets[k].base;
  }
  for (const LinearPatch& p : patches) {
    for (std::size_t k = 0; k < N; ++k) {
      const bool below = p.hi <= a[k];
      base[k] += below ? p.area : 0.0;
      if (!below && p.lo < b[k]) add_to_bracket(brackets[k], p);
    }
  }
  for (std::size_t k = 0; k < N; ++k) brackets[k].base = base[k];
}

void narrow_fresh(std::span<Bracket> brackets, std::span<const LinearPatch> patches) {
  for (; brackets.size() >= 3; brackets = brackets.subspan(3)) {
    narrow_together<3>(brackets.first(3), patches);
  }
  if (brackets.size() == 2) narrow_together<2>(brackets, patches);
  if (brackets.size() == 1) narrow_together<1>(brackets, patches);
}

// Every fresh bracket narrowed over all patches: in two halves side by side, each half's
// brackets sharing their passes over the patches, range after range; `along` rides on the
// second half's pass, which has no more brackets than the first (or is its own pass).
void narrow_all(std::span<Bracket> brackets, const PatchSource& patches,
                const PatchRangeVisitor& along) {
  const std::size_t half = (brackets.size() + 1) / 2;
  const auto narrow_over_all = [&](std::span<Bracket> some, const PatchRangeVisitor* rider) {
    if (some.empty() && !rider) return;  // one bracket: no second pass to make the patches for
    for_each_patch_range(patches, [&](std::span<const LinearPatch> range) {
      narrow_fresh(some, range);
      if (rider) (*rider)(range);
    });
  };
  tbb::parallel_invoke([&] { narrow_over_all(brackets.first(half), nullptr); },
                       [&] { narrow_over_all(brackets.subspan(half), along ? &along : nullptr); });
}

// With no corner value inside (a, b), F is base + spanning there: bisect it.
double solve_in_bracket(const Bracket& bracket, double target) {
  const auto at = [&](double t) { return bracket.base + bracket.spanning(t - bracket.a); };
  // Below target just short of b: the missing area is an atom (a constant patch) at b.
  if (at(bracket.b) < target) return bracket.b;
  double below = bracket.a, above = bracket.b;
  for (;;) {
    const double t = below + (above - below) / 2;
    if (t <= below || t >= above) return above;
    (at(t) >= target ? above : below) = t;
  }
}

double quantile_in(Bracket bracket, std::span<const double> sorted, double target) {
  for (;;) {
    const auto begin = std::upper_bound(sorted.begin(), sorted.end(), bracket.a);
    const auto end = std::lower_bound(begin, sorted.end(), bracket.b);
    if (begin == end) return solve_in_bracket(bracket, target);
    const std::vector<double> splits =
        rank_splits(sorted, static_cast<std::size_t>(begin - sorted.begin()),
                    static_cast<std::size_t>(end - sorted.begin()));
    const std::vector<double> at_most = area_at_most_each(StoredPatches(bracket.partial), splits);
    std::size_t j = 0;
    while (j < splits.size() &&
           bracket.base + bracket.spanning(splits[j] - bracket.a) + at_most[j] < target) {
      ++j;
    }
    const double a = j == 0 ? bracket.a : splits[j - 1];
    const double b = j == splits.size() ? bracket.b : splits[j];
    // The narrower bracket's partial patches are some of these: reserved at their count,
    // it is filled without growing (each growth a fresh block, docs/PERFORMANCE.md).
    const Buffer<LinearPatch> partial = std::move(bracket.partial);
    bracket.partial.reserve(partial.size());
    narrow(bracket, partial, a, b);
  }
}

// The first step's split points: the smallest value, so that every fraction beyond an atom
// there has a lower end to its bracket, then values spread evenly by rank.
std::vector<double> first_splits(std::span<const double> values) {
  const std::size_t count = values.size();
  const std::size_t wanted = std::min(count, kSplits);
  std::vector<std::size_t> ranks{0};
  for (std::size_t k = 1; k <= wanted; ++k) {
    const std::size_t rank = (count * k) / wanted - 1;
    if (rank > ranks.back()) ranks.push_back(rank);
  }
  std::vector<double> splits;
  for (const double value : values_at_ranks(values, ranks)) {
    if (splits.empty() || value != splits.back()) splits.push_back(value);
  }
  return splits;
}

// The corner values strictly inside (a, b), ascending, each plus +0.0 (as the splits).
std::vector<double> values_inside(std::span<const double> values, double a, double b) {
  std::vector<double> inside;
  for (const double v : values) {
    if (a < v && v < b) inside.push_back(v + 0.0);
  }
  sort_values(inside);
  return inside;
}

}  // namespace

// The splits come out plus +0.0 (-0.0 as +0.0): equal values are then equal bit patterns,
// and no result can come out as a negative zero.
AreaQuantiles::AreaQuantiles(std::span<const double> values)
    : values_(values), splits_(values.empty() ? std::vector<double>{} : first_splits(values)) {}

std::vector<double> AreaQuantiles::zero() const {
  return SplitSums(2 * splits_.size() + 1, 0.0);
}

std::vector<double> AreaQuantiles::block(std::span<const LinearPatch> patches) const {
  return split_sums(patches, splits_);
}

void AreaQuantiles::combine(std::vector<double>& acc, const std::vector<double>& part) {
  add_split_sums(acc, part);
}

std::vector<double> AreaQuantiles::quantiles(const PatchSource& patches,
                                             std::span<const double> fractions,
                                             const std::vector<double>& sums,
                                             const PatchRangeVisitor& along) const {
  std::vector<double> result(fractions.size(), std::numeric_limits<double>::quiet_NaN());
  // The first step ran over all patches once, shared by every fraction.
  const std::vector<double> at_most = at_most_from(sums, splits_.size());
  if (at_most.empty() || !(at_most.back() > 0)) {  // no values, or no area
    if (along) for_each_patch_range(patches, along);
    return result;
  }
  const double total = at_most.back();
  // Each fraction's first bracket: (splits[j - 1], splits[j]), j = 0 when the fraction lies
  // at the smallest value. Fractions sharing a bracket share its narrowing.
  std::vector<std::size_t> first_bracket(fractions.size());
  for (std::size_t f = 0; f < fractions.size(); ++f) {
    const double target = std::clamp(fractions[f], 0.0, 1.0) * total;
    first_bracket[f] = static_cast<std::size_t>(
        std::find_if(at_most.begin(), at_most.end(), [&](double F) { return F >= target; }) -
        at_most.begin());
  }
  std::vector<std::size_t> opened;  // the distinct j > 0, ascending
  for (const std::size_t j : first_bracket) {
    if (j > 0 && std::find(opened.begin(), opened.end(), j) == opened.end()) opened.push_back(j);
  }
  std::sort(opened.begin(), opened.end());
  std::vector<Bracket> brackets(opened.size());
  const std::size_t reserved =
      std::min(patches.size(), kPartialPerValue * values_.size() / kSplits);
  for (std::size_t k = 0; k < opened.size(); ++k) {
    brackets[k].a = splits_[opened[k] - 1];
    brackets[k].b = splits_[opened[k]];
    brackets[k].partial.reserve(reserved);
  }
  narrow_all(brackets, patches, along);
  tbb::parallel_for(std::size_t{0}, fractions.size(), [&](std::size_t f) {
    const std::size_t j = first_bracket[f];
    if (j == 0) {
      result[f] = splits_[0];
      return;
    }
    const double target = std::clamp(fractions[f], 0.0, 1.0) * total;
    const std::vector<double> inside = values_inside(values_, splits_[j - 1], splits_[j]);
    const auto k = static_cast<std::size_t>(std::lower_bound(opened.begin(), opened.end(), j) -
                                            opened.begin());
    result[f] = quantile_in(brackets[k], inside, target);
  });
  return result;
}

std::vector<double> area_quantiles(const PatchSource& patches, std::span<const double> values,
                                   std::span<const double> fractions) {
  const AreaQuantiles search(values);
  return search.quantiles(
      patches, fractions,
      reduce_patch_blocks(
          patches, search.zero(),
          [&](std::span<const LinearPatch> block) { return search.block(block); },
          AreaQuantiles::combine));
}

}  // namespace ncv
