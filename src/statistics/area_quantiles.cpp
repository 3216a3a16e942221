#include "statistics/area_quantiles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/parallel_for.h>

#include "util/ordered_reduce.hpp"

namespace ncv {

namespace {

constexpr std::size_t kPatchBlock = 1 << 16;
// Split points per refinement step: each step leaves at most 1/kSplits of the corner
// values inside the bracket, so a few steps reach a bracket free of them.
constexpr std::size_t kSplits = 32;

// Distribution function at each split point (ascending): patches wholly at or below a
// split add their whole area from there on, patches straddling it their closed form.
std::vector<double> area_at_most_each(std::span<const LinearPatch> patches,
                                      const std::vector<double>& splits) {
  const std::size_t m = splits.size();
  using Sums = std::vector<double>;  // [0, m): partial areas, [m, 2m]: whole-area steps
  Sums sums = ordered_reduce(
      patches.size(), kPatchBlock, Sums(2 * m + 1, 0.0),
      [&](std::size_t begin, std::size_t end) {
        Sums part(2 * m + 1, 0.0);
        for (std::size_t i = begin; i < end; ++i) {
          const LinearPatch& p = patches[i];
          const auto first = std::lower_bound(splits.begin(), splits.end(), p.lo);
          const auto whole = std::lower_bound(first, splits.end(), p.hi);
          for (auto s = first; s != whole; ++s) part[s - splits.begin()] += area_at_most(p, *s);
          part[m + static_cast<std::size_t>(whole - splits.begin())] += p.area;
        }
        return part;
      },
      [](Sums& acc, const Sums& part) {
        for (std::size_t k = 0; k < acc.size(); ++k) acc[k] += part[k];
      });
  std::vector<double> at_most(m);
  double whole = 0;
  for (std::size_t j = 0; j < m; ++j) {
    whole += sums[m + j];
    at_most[j] = whole + sums[j];
  }
  return at_most;
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
  std::vector<LinearPatch> partial;
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
    const std::vector<double> at_most = area_at_most_each(bracket.partial, splits);
    std::size_t j = 0;
    while (j < splits.size() &&
           bracket.base + bracket.spanning(splits[j] - bracket.a) + at_most[j] < target) {
      ++j;
    }
    const double a = j == 0 ? bracket.a : splits[j - 1];
    const double b = j == splits.size() ? bracket.b : splits[j];
    const std::vector<LinearPatch> partial = std::move(bracket.partial);
    narrow(bracket, partial, a, b);
  }
}

// Puts the values of the given ranks (ascending) at their sorted positions, every other
// value between the ranks it lies between: a multi-way nth_element, splitting at the
// middle rank and recursing, in O(n log ranks) instead of a full sort.
void select_ranks(std::span<double> values, std::span<const std::size_t> ranks,
                  std::size_t offset) {
  if (ranks.empty()) return;
  const std::size_t middle = ranks.size() / 2;
  const std::size_t at = ranks[middle] - offset;
  std::nth_element(values.begin(), values.begin() + at, values.end());
  select_ranks(values.first(at), ranks.first(middle), offset);
  select_ranks(values.subspan(at + 1), ranks.subspan(middle + 1), offset + at + 1);
}

// The first step's split points: the smallest value, so that every fraction beyond an atom
// there has a lower end to its bracket, then values spread evenly by rank; each with the
// position it holds in the selected array.
struct RankSplits {
  std::vector<double> values;
  std::vector<std::size_t> positions;
};

RankSplits first_splits(std::vector<double>& values) {
  const std::size_t count = values.size();
  const std::size_t wanted = std::min(count, kSplits);
  std::vector<std::size_t> ranks{0};
  for (std::size_t k = 1; k <= wanted; ++k) {
    const std::size_t rank = (count * k) / wanted - 1;
    if (rank > ranks.back()) ranks.push_back(rank);
  }
  select_ranks(values, ranks, 0);
  RankSplits splits;
  for (const std::size_t rank : ranks) {
    if (!splits.values.empty() && values[rank] == splits.values.back()) continue;
    splits.values.push_back(values[rank]);
    splits.positions.push_back(rank);
  }
  return splits;
}

}  // namespace

std::vector<double> area_quantiles(std::span<const LinearPatch> patches,
                                   std::span<const double> values,
                                   std::span<const double> fractions) {
  std::vector<double> result(fractions.size(), std::numeric_limits<double>::quiet_NaN());
  if (values.empty()) return result;
  // Adding +0.0 turns -0.0 into +0.0: equal values are then equal bit patterns, and no
  // result can come out as a negative zero.
  std::vector<double> selected(values.size());
  std::transform(values.begin(), values.end(), selected.begin(), [](double v) { return v + 0.0; });
  const RankSplits splits = first_splits(selected);
  // The first step runs over all patches once, shared by every fraction.
  const std::vector<double> at_most = area_at_most_each(patches, splits.values);
  const double total = at_most.back();
  if (!(total > 0)) return result;
  tbb::parallel_for(std::size_t{0}, fractions.size(), [&](std::size_t f) {
    const double target = std::clamp(fractions[f], 0.0, 1.0) * total;
    const std::size_t j = static_cast<std::size_t>(
        std::find_if(at_most.begin(), at_most.end(), [&](double F) { return F >= target; }) -
        at_most.begin());
    if (j == 0) {
      result[f] = splits.values[0];
      return;
    }
    // The values strictly inside the bracket all lie between the two split positions.
    std::vector<double> inside(selected.begin() + splits.positions[j - 1] + 1,
                               selected.begin() + splits.positions[j]);
    std::sort(inside.begin(), inside.end());
    Bracket bracket;
    narrow(bracket, patches, splits.values[j - 1], splits.values[j]);
    result[f] = quantile_in(std::move(bracket), inside, target);
  });
  return result;
}

}  // namespace ncv
