#include <catch2/catch.hpp>

#include "statistics/value_range.hpp"
#include "util/error.hpp"

using namespace ncv;

TEST_CASE("a value range reads LO:HI or R for a symmetric range", "[value_range]") {
  const ValueRange given = parse_value_range("-0.25:1.5");
  CHECK(given.lo == -0.25);
  CHECK(given.hi == 1.5);
  const ValueRange symmetric = parse_value_range("0.3");
  CHECK(symmetric.lo == -0.3);
  CHECK(symmetric.hi == 0.3);
}

TEST_CASE("a value range is refused as a range, not as a tolerance", "[value_range]") {
  const auto message = [](const char* text) {
    try {
      parse_value_range(text);
    } catch (const UsageError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  CHECK(message("1:-1") == "range '1:-1': the lower limit exceeds the upper limit");
  CHECK(message("0") == "range '0' has no width: its lower limit must be below its upper limit");
  CHECK(message("2:2") ==
        "range '2:2' has no width: its lower limit must be below its upper limit");
  CHECK(message("wide") == "range 'wide': 'wide' is not a number");
  CHECK(message("1:inf") == "range '1:inf': limits must be finite");
}
