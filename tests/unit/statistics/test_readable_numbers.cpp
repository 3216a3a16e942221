// Numbers for people: the part's resolution, the units, rounding noise as 0.
#include <catch2/catch.hpp>

#include "statistics/readable_numbers.hpp"

using ncv::BoundingBox;
using ncv::NumberStyle;
using ncv::Vec3;

namespace {

BoundingBox box(double x, double y, double z) {
  BoundingBox b;
  b.extend(Vec3(0, 0, 0));
  b.extend(Vec3(x, y, z));
  return b;
}

}  // namespace

TEST_CASE("lengths round to a millionth of the part's diagonal", "[numbers]") {
  // The bundled mould core: 120 x 80 x 30, diagonal 147: resolution 1.5e-4, 4 decimals.
  const NumberStyle core = ncv::number_style(box(120, 80, 30), "mm");
  CHECK(core.length_decimals == 4);
  CHECK(core.area_decimals == 2);
  CHECK(core.length(0.82461309432983398) == "0.8246");
  CHECK(core.length_with_units(-0.3) == "-0.3000 mm");
  CHECK(core.area_with_units(26980.417013505412) == "26980.42 mm\u00b2");
  CHECK(core.point(Vec3(109.84375, 10.15625, 5.8246)) == "(109.8438, 10.1562, 5.8246)");
  // A 10 mm box: diagonal 17.3, resolution 1.7e-5, 5 decimals; a 2 m part: 3.
  CHECK(ncv::number_style(box(10, 10, 10), "mm").length_decimals == 5);
  CHECK(ncv::number_style(box(2000, 1000, 500), "mm").length_decimals == 3);
  CHECK(ncv::number_style(box(5, 3, 1), "in").area_with_units(2) == "2.00000 in\u00b2");
}

TEST_CASE("rounding noise reads 0, never -0 or 1e-14", "[numbers]") {
  const NumberStyle style = ncv::number_style(box(120, 80, 30), "mm");
  CHECK(style.length(-1.5888e-14) == "0");
  CHECK(style.length(4.9e-5) == "0");
  CHECK(style.length(-4.9e-5) == "0");
  CHECK(style.length(0) == "0");
  CHECK(style.length(-0.0) == "0");
  CHECK(style.length(6e-5) == "0.0001");
  CHECK(style.length(-6e-5) == "-0.0001");
  CHECK(ncv::fixed_or_zero(2.6, 0) == "3");
}

TEST_CASE("a part without extent gets the default style", "[numbers]") {
  const NumberStyle flat = ncv::number_style(box(0, 0, 0), "mm");
  CHECK(flat.length_decimals == 4);
  CHECK(flat.units == "mm");
  CHECK(ncv::number_style(BoundingBox{}, "mm").length_decimals == 4);
}
