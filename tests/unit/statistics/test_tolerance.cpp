#include <catch2/catch.hpp>

#include <cmath>

#include "statistics/tolerance.hpp"
#include "util/error.hpp"

using ncv::parse_tolerance;
using ncv::Tolerance;

TEST_CASE("an asymmetric tolerance reads lower:upper", "[stats]") {
  const Tolerance zone = parse_tolerance("-0.05:0.1");
  CHECK(zone.lower == -0.05);
  CHECK(zone.upper == 0.1);
  CHECK(parse_tolerance("0:0.2") == Tolerance{0, 0.2});
  CHECK(parse_tolerance("-0.3:-0.1") == Tolerance{-0.3, -0.1});
  CHECK(parse_tolerance("1e-3:2E-3") == Tolerance{0.001, 0.002});
}

TEST_CASE("a single value is a symmetric tolerance", "[stats]") {
  CHECK(parse_tolerance("0.1") == Tolerance{-0.1, 0.1});
  CHECK(parse_tolerance("0") == Tolerance{0, 0});
}

TEST_CASE("malformed tolerances are usage errors", "[stats]") {
  for (const char* text :
       {"", ":", "abc", "0.1:", ":0.1", "0.1x", "0.1 ", " 0.1", "+0.1", "nan", "inf", "-inf:1",
        "0:nan", "1e999", "0.2:0.1", "-0.1", "1:2:3", "0.1,0.2", "--1:1"}) {
    INFO("tolerance '" << text << "'");
    CHECK_THROWS_AS(parse_tolerance(text), ncv::UsageError);
  }
}

TEST_CASE("the error message names the tolerance and the fault", "[stats]") {
  CHECK_THROWS_WITH(parse_tolerance("0.2:0.1"),
                    Catch::Contains("0.2:0.1") && Catch::Contains("lower limit exceeds"));
  CHECK_THROWS_WITH(parse_tolerance("0.1abc"), Catch::Contains("'abc'"));
}

TEST_CASE("a tolerance prints back to the same limits", "[stats]") {
  for (const Tolerance zone :
       {Tolerance{-0.05, 0.1}, Tolerance{-1.0 / 3, 2.0 / 7}, Tolerance{0, 0}}) {
    CHECK(parse_tolerance(ncv::to_string(zone)) == zone);
  }
  CHECK(ncv::to_string({-0.05, 0.1}) == "-0.05:0.1");
}

TEST_CASE("classification puts the limits inside the zone", "[stats]") {
  const Tolerance zone{-0.05, 0.1};
  CHECK(ncv::classify(-0.05, zone) == ncv::ToleranceClass::within);
  CHECK(ncv::classify(0.1, zone) == ncv::ToleranceClass::within);
  CHECK(ncv::classify(std::nextafter(0.1, 1.0), zone) == ncv::ToleranceClass::excess);
  CHECK(ncv::classify(std::nextafter(-0.05, -1.0), zone) == ncv::ToleranceClass::gouge);
}
