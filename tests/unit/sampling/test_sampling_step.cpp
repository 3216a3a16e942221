#include <catch2/catch.hpp>

#include "sampling/sampling_step.hpp"
#include "util/error.hpp"

using namespace ncv;

TEST_CASE("steps are absolute or a percentage of the diagonal", "[sampling]") {
  const SamplingStep absolute = SamplingStep::parse("0.05");
  CHECK_FALSE(absolute.relative);
  CHECK(absolute.resolve(1000) == 0.05);
  const SamplingStep relative = SamplingStep::parse("0.1%");
  CHECK(relative.relative);
  CHECK(relative.resolve(150) == Approx(0.15));
  CHECK(SamplingStep::parse("2e-3").value == 0.002);
}

TEST_CASE("bad steps are refused", "[sampling]") {
  for (const char* bad :
       {"", "0", "-1", "nan", "inf", "0%", "1%%", "abc", "1mm", "%", " 1", "100.5%", "200%"}) {
    INFO(bad);
    CHECK_THROWS_AS(SamplingStep::parse(bad), UsageError);
  }
  CHECK(SamplingStep::parse("100%").value == 100);  // the diagonal itself is the limit
}
