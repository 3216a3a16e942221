// How the distance step decides on which side of the reference surface a point lies.
// Positive always means outside the reference solid, negative inside (docs/METHOD.md
// "Signed distance").
#pragma once

#include <cstdint>

#include "util/enum_names.hpp"

namespace ncv {

enum class SignMethod : std::uint8_t {
  automatic = 0,     // pseudonormal for a closed, consistently oriented surface, else winding
  pseudonormal = 1,  // angle-weighted pseudonormal of the closest feature (Baerentzen-Aanaes)
  winding = 2,       // generalized winding number (Jacobson et al.), inside where >= 0.5
  paper = 3,         // the paper's rule: the sample's own normal N_p, positive when N_p.(p-c) > 0
};

inline constexpr EnumName<SignMethod> kSignMethodNames[] = {
    {SignMethod::automatic, "auto"},
    {SignMethod::pseudonormal, "pseudonormal"},
    {SignMethod::winding, "winding"},
    {SignMethod::paper, "paper"}};

}  // namespace ncv
