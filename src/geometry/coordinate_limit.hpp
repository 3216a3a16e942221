// The largest coordinate magnitude ncverify accepts in a mesh or a query point.
#pragma once

namespace ncv {

// Far beyond any part in any unit, and far enough below the double range that squared
// distances and cross products of coordinates cannot overflow.
inline constexpr double kMaxCoordinate = 1e100;

}  // namespace ncv
