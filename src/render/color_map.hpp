// Colour maps from signed error to RGB (docs/METHOD.md "Colouring").
//
//   tolerance  the paper's scheme: green inside the tolerance zone, red for excess and
//              blue for gouge, from a light saturated shade at the limit (amber, azure) to
//              a deep one at the end of the range (red at hi, indigo at lo) and beyond.
//   diverging  blue - white - red (ColorBrewer RdBu) over [lo, hi], white at 0 when the
//              range contains it, else at its middle.
//   turbo      Google's Turbo rainbow over [lo, hi].
// A value without a sample (NaN) is grey in every map.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "statistics/area_histogram.hpp"
#include "statistics/tolerance.hpp"
#include "util/enum_names.hpp"

namespace ncv {

using Rgb = std::array<std::uint8_t, 3>;

inline constexpr Rgb kNoValueColor{128, 128, 128};

enum class ColorMapKind { tolerance, diverging, turbo };

inline constexpr EnumName<ColorMapKind> kColorMapNames[] = {{ColorMapKind::tolerance, "tolerance"},
                                                            {ColorMapKind::diverging, "diverging"},
                                                            {ColorMapKind::turbo, "turbo"}};

// A point of the map: between consecutive stops the colour is linear in RGB; two stops at
// one value mark a jump.
struct ColorStop {
  double value = 0;
  Rgb color{};
};

struct ColorMap {
  ColorMapKind kind = ColorMapKind::diverging;
  ValueRange range;
  // Required by the tolerance map (make_color_map checks; rgb throws without it), and
  // marked in legends of the others.
  std::optional<Tolerance> tolerance;

  Rgb rgb(double value) const;
  // The map over its range, ascending, exact for the tolerance and diverging maps and a
  // dense sampling of Turbo.
  std::vector<ColorStop> stops() const;
  // One line naming the map and its parameters, e.g. for a PLY comment.
  std::string description() const;
};

// Throws UsageError when the range is not finite and ordered, or the tolerance map has no
// tolerance.
ColorMap make_color_map(ColorMapKind kind, ValueRange range,
                        const std::optional<Tolerance>& tolerance);

}  // namespace ncv
