// area_quantiles (statistics/area_quantiles.hpp) on random fields with atoms, ties, negative
// zeros and a dense cluster of rounding noise: the same numbers, to the bit, as the
// implementation before its passes were shared and parallelised (commit 3adc5c3), the same
// numbers on any thread count, and the exact quantile of the distribution (a plain
// sort-and-sum reference).
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include <tbb/global_control.h>

#include "geometry/linear_patch.hpp"
#include "statistics/area_quantiles.hpp"

namespace {

std::uint64_t next_bits(std::uint64_t& state) {  // splitmix64: the same on every platform
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

double unit(std::uint64_t& state) {  // in [0, 1), 53 random bits
  return static_cast<double>(next_bits(state) >> 11) * 0x1p-53;
}

struct Field {
  std::vector<ncv::LinearPatch> patches;
  std::vector<double> values;  // every corner value
};

Field random_field(std::uint64_t seed, std::size_t count) {
  std::uint64_t state = seed;
  std::vector<double> point(count + 2);
  for (double& v : point) {
    const double u = unit(state);
    if (u < 0.35) {
      v = unit(state) * 0x1p-50;  // the cluster of rounding noise
    } else if (u < 0.45) {
      v = u < 0.4 ? 0.0 : -0.0;
    } else if (u < 0.55) {
      v = 0.125 * static_cast<double>(next_bits(state) % 5);  // exact ties
    } else if (u < 0.97) {
      v = (unit(state) - 0.4) * 0.2;
    } else {
      v = (unit(state) - 0.3) * 6;  // the tail
    }
  }
  Field field;
  for (std::size_t k = 0; k < count; ++k) {
    const double area = next_bits(state) % 8 == 0 ? 0.25 : 0.5 + unit(state);
    const bool atom = next_bits(state) % 16 == 0;
    const double a = point[k], b = atom ? a : point[k + 1], c = atom ? a : point[k + 2];
    field.patches.push_back(ncv::make_linear_patch(area, a, b, c));
    field.values.insert(field.values.end(), {a, b, c});
  }
  return field;
}

const std::vector<double> kFractions = {0, 0.01, 0.05, 0.25, 0.3, 0.5, 0.75, 0.95, 0.99, 1};

struct Golden {
  std::uint64_t seed;
  std::size_t count;
  std::vector<std::uint64_t> bits;  // per kFractions
};

// Printed by the implementation of commit 3adc5c3 (the statistics' reference results).
const std::vector<Golden> kGolden = {
    {1,
     1000,
     {0xbffaca3fb45fd728u, 0xbfb0048b46eced58u, 0xbfa0ff2d9c32b804u, 0xbf0513e12cc59068u,
      0x3cad324e35e565d0u, 0x3f82d1ea7908412fu, 0x3fab631e2795027du, 0x3fd32ff9eb843f05u,
      0x3ff2e1edcd51fc7du, 0x4010b928bbe8ca33u}},
    {1,
     200000,
     {0xbffcca1c89050892u, 0xbfd18b9ee4eb5d05u, 0xbfa4293cf3a3a6dau, 0xbf1ebbbbce2d87d2u,
      0x3cb027b8f3d57bdbu, 0x3f86defa7c4dcc00u, 0x3fadfa5c7f5c145au, 0x3fd56063bd2b90bau,
      0x3ff7f28033e3fe2eu, 0x4010cca60e6c683du}},
    {2,
     1000,
     {0xbff7f949f82b3532u, 0xbfba49335cc80b8au, 0xbfa1879786225dc1u, 0x0000000000000000u,
      0x3cb8126dab780630u, 0x3f8adfb50aaf3efau, 0x3fae9aa078288666u, 0x3fd4190facd53fd9u,
      0x3ff7b3529bb28659u, 0x4010490e5f0c6a58u}},
    {2,
     200000,
     {0xbffcc575addac808u, 0xbfd3592c13f242a5u, 0xbfa4834a368c24b0u, 0xbf2e6cece2f0937bu,
      0x3caf0979f845c8bbu, 0x3f8645d278b04a64u, 0x3fad9c2dd749fb70u, 0x3fd4da6c49fb8bc1u,
      0x3ff7310e2a3512d4u, 0x4010cc95ee887920u}},
    {3,
     1000,
     {0xbff77dd247c27c6au, 0xbfcec283411d5bd9u, 0xbfa30d5814586a96u, 0xbf53bc43e099c6d5u,
      0x3c97b067bf1012a5u, 0x3f7f00b024575edbu, 0x3fa9ebb6be8898b9u, 0x3fd4668de8282472u,
      0x3ff69cf3f5ea0db3u, 0x400ea2efcc697a1au}},
    {3,
     200000,
     {0xbffcc6ac035eba22u, 0xbfd169f049908b3eu, 0xbfa435d4896662a6u, 0xbf21d5ea5c995549u,
      0x3caf9676203bce76u, 0x3f8688bb84e607e8u, 0x3fadf39a37774a2du, 0x3fd501e3dd522578u,
      0x3ff7596721ac9bb2u, 0x4010cc30790a223eu}},
};

// The area at most t, summed patch by patch.
double distribution(const std::vector<ncv::LinearPatch>& patches, double t) {
  double sum = 0;
  for (const ncv::LinearPatch& p : patches) sum += ncv::area_at_most(p, t);
  return sum;
}

// The smallest t with F(t) >= q F(max): the corner values sorted, the bracket of consecutive
// ones found by F, then bisection on F inside it.
double reference_quantile(const Field& field, double q) {
  std::vector<double> sorted = field.values;
  std::sort(sorted.begin(), sorted.end());
  const double target = q * distribution(field.patches, sorted.back());
  const auto reached = [&](double t) { return distribution(field.patches, t) >= target; };
  const auto b =
      std::partition_point(sorted.begin(), sorted.end(), [&](double v) { return !reached(v); });
  if (b == sorted.begin()) return *b;
  double below = *(b - 1), above = *b;
  for (int k = 0; k < 200 && below < above; ++k) {
    const double t = below + (above - below) / 2;
    if (t <= below || t >= above) break;
    (reached(t) ? above : below) = t;
  }
  return above;
}

}  // namespace

TEST_CASE("area quantiles are the reference implementation's to the bit", "[stats][quantiles]") {
  for (const Golden& golden : kGolden) {
    const Field field = random_field(golden.seed, golden.count);
    const std::vector<double> q =
        ncv::area_quantiles(ncv::StoredPatches(field.patches), field.values, kFractions);
    for (std::size_t k = 0; k < kFractions.size(); ++k) {
      INFO("seed " << golden.seed << ", " << golden.count << " patches, fraction "
                   << kFractions[k]);
      CHECK(std::bit_cast<std::uint64_t>(q[k]) == golden.bits[k]);
    }
  }
}

TEST_CASE("area quantiles do not depend on the thread count", "[stats][quantiles]") {
  const Field field = random_field(7, 300000);
  const auto run = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return ncv::area_quantiles(ncv::StoredPatches(field.patches), field.values, kFractions);
  };
  const std::vector<double> one = run(1), two = run(2), three = run(3);
  for (std::size_t k = 0; k < kFractions.size(); ++k) {
    CHECK(std::bit_cast<std::uint64_t>(one[k]) == std::bit_cast<std::uint64_t>(two[k]));
    CHECK(std::bit_cast<std::uint64_t>(one[k]) == std::bit_cast<std::uint64_t>(three[k]));
  }
}

// Where the distribution is flat (near the largest value) a quantile's position is
// ill-conditioned: both are compared by the area below them, and the result must invert the
// distribution (F reaches the target at it, not just below it).
TEST_CASE("area quantiles match a sort-based reference", "[stats][quantiles]") {
  for (const std::uint64_t seed : {11, 12, 13}) {
    const Field field = random_field(seed, 3000);
    const std::vector<double> q =
        ncv::area_quantiles(ncv::StoredPatches(field.patches), field.values, kFractions);
    const double total =
        distribution(field.patches, *std::max_element(field.values.begin(), field.values.end()));
    const double tolerance = 1e-9 * total;
    for (std::size_t k = 0; k < kFractions.size(); ++k) {
      INFO("seed " << seed << ", fraction " << kFractions[k]);
      const double target = kFractions[k] * total;
      const double reference = reference_quantile(field, kFractions[k]);
      CHECK(distribution(field.patches, q[k]) ==
            Approx(distribution(field.patches, reference)).margin(tolerance));
      CHECK(distribution(field.patches, q[k]) >= target - tolerance);
      CHECK(distribution(field.patches, std::nextafter(q[k], -INFINITY)) <= target + tolerance);
    }
  }
}
