// How reports meant for people write numbers (the text report, the HTML report, the
// pictures): to the resolution the measurement supports, with the units, and rounding
// noise as 0. Data meant for programs (JSON, CSV) keeps every digit instead.
//
// The resolution is a millionth of the part's bounding-box diagonal, rounded down to a
// power of ten: the meshes come from STL files, whose single-precision coordinates carry a
// relative error of 6e-8, and the machining and CAD tolerances they encode are far
// coarser. A 150 mm part gets 4 decimals (0.1 um), a 15 mm part 5. Areas get the
// resolution of diagonal x length resolution.
#pragma once

#include <string>

#include "geometry/bounding_box.hpp"
#include "geometry/vec3.hpp"

namespace ncv {

struct NumberStyle {
  int length_decimals = 4;
  int area_decimals = 2;
  std::string units = "mm";

  // "0.8246"; a value that rounds to zero is "0", never "-0.0000" or "1.6e-14".
  std::string length(double value) const;
  // "0.8246 mm".
  std::string length_with_units(double value) const;
  std::string area(double value) const;
  std::string area_with_units(double value) const;  // "26980.42 mm²"
  std::string point(Vec3 p) const;                  // "(12.5000, 3.0000, 20.0000)"
};

// The style for a part of this extent; a box without extent gets the defaults above.
NumberStyle number_style(const BoundingBox& part, std::string units);

// value rounded to `decimals` places as text, "0" when it rounds to zero.
std::string fixed_or_zero(double value, int decimals);

}  // namespace ncv
