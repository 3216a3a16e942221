// Sample counts for steps far too small for any machine: the estimate saturates instead of
// wrapping around (a wrapped count could pass the memory guard), and sampling refuses a
// lattice it cannot address instead of writing past arrays sized from a wrapped count.
#include <catch2/catch.hpp>

#include <limits>

#include "nominal_fixtures.hpp"
#include "sampling/sampling.hpp"
#include "util/error.hpp"
#include "util/memory_guard.hpp"

using namespace ncv;

namespace {

// Twelve triangles of 50 mm^2: at a step of 1e-9 each would have about 2 * 10^18 samples.
Mesh box() {
  return fixtures::box({0, 0, 0}, {10, 10, 10});
}

}  // namespace

TEST_CASE("sample counts beyond 2^64 saturate and are refused", "[sampling]") {
  const Mesh mesh = box();
  // It used to wrap to 5,553,255,938,290,448,356.
  CHECK(predicted_sample_count(mesh, plan_sampling(mesh, 1e-9, SamplingScheme::all)) ==
        std::numeric_limits<std::uint64_t>::max());
  // It used to escape as std::length_error from the arrays' resize.
  CHECK_THROWS_MATCHES(sample_mesh(box(), 1e-9, SamplingScheme::all), UsageError,
                       Catch::Message("sampling at step 1e-09 would give more than 2^64 samples"));
  CHECK(predicted_sample_count(mesh, plan_sampling(mesh, 1.0, SamplingScheme::all)) ==
        sample_mesh(box(), 1.0, SamplingScheme::all).sample_count());
}

TEST_CASE("the memory guard states estimates beyond 2^64 bytes", "[sampling]") {
  // Converting 3.2e20 to an integer for the message was undefined behaviour ("0 B").
  CHECK_THROWS_WITH(check_memory_budget("sampling", 3.2e20, false),
                    Catch::Contains("would need about 3.2e+11 GB of memory"));
  CHECK_NOTHROW(check_memory_budget("sampling", 3.2e20, true));
}
