// Passes over patches: a sum fed range by range in index order is the parallel pass's sum to
// the bit, wherever the ranges are cut.
#include <catch2/catch.hpp>

#include <random>
#include <span>
#include <vector>

#include <tbb/global_control.h>

#include "geometry/linear_patch.hpp"
#include "geometry/patch_source.hpp"
#include "statistics/patch_passes.hpp"

using ncv::kPatchBlock;
using ncv::LinearPatch;

namespace {

std::vector<LinearPatch> random_patches(std::size_t count, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> value(-2.0, 3.0), area(0.0, 1e-3);
  std::vector<LinearPatch> patches(count);
  for (LinearPatch& p : patches) {
    // Values of mixed magnitudes, so that the order of the additions shows in the last bits.
    p = ncv::make_linear_patch(area(random), value(random) * 1e3, value(random),
                               value(random) * 1e-6);
  }
  return patches;
}

double term(const LinearPatch& p) {
  return ncv::squared_integral(p, 0.25);
}

double parallel_sum(const ncv::PatchSource& source) {
  return ncv::reduce_patch_blocks(
      source, 0.0,
      [](std::span<const LinearPatch> block) {
        double sum = 0;
        for (const LinearPatch& p : block) sum += term(p);
        return sum;
      },
      [](double& acc, double part) { acc += part; });
}

}  // namespace

TEST_CASE("a sum fed range by range is the parallel pass's sum to the bit", "[stats]") {
  const tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 2);
  // Whole blocks only (the last block ends where the patches end), a partial last block,
  // less than one block, one patch.
  for (const std::size_t count :
       {3 * kPatchBlock, 2 * kPatchBlock + 4097, kPatchBlock - 3, std::size_t{1}}) {
    const std::vector<LinearPatch> patches = random_patches(count, count);
    const ncv::StoredPatches source(patches);
    const double expected = parallel_sum(source);
    std::mt19937_64 random(count + 1);
    for (int cut = 0; cut < 4; ++cut) {
      // Ranges of random lengths, some straddling block boundaries; and the passes' own
      // ranges of 8192 (cut 0).
      std::uniform_int_distribution<std::size_t> length(1, cut == 0 ? 1 : 3 * kPatchBlock / 2);
      ncv::OrderedPatchSum sum(term);
      for (std::size_t begin = 0; begin < count;) {
        const std::size_t end =
            cut == 0 ? std::min(count, begin + 8192) : std::min(count, begin + length(random));
        sum.add(std::span(patches).subspan(begin, end - begin));
        begin = end;
      }
      INFO("count " << count << ", cut " << cut);
      CHECK(sum.sum() == expected);
    }
  }
  CHECK(ncv::OrderedPatchSum(term).sum() == 0.0);
}
