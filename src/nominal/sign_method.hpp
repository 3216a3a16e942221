// How the distance step decides on which side of the nominal a sample lies. Positive always
// means outside the nominal solid (excess material), negative inside (gouge).
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace ncv {

enum class SignMethod : std::uint8_t {
  automatic = 0,     // pseudonormal for a closed, consistently oriented nominal, else winding
  pseudonormal = 1,  // angle-weighted pseudonormal of the closest feature (Baerentzen-Aanaes)
  winding = 2,       // generalized winding number of the nominal (Jacobson et al.), inside >= 0.5
  paper = 3,         // the paper's rule: the sample's own normal N_p, positive when N_p.(p-c) > 0
};

std::string_view sign_method_name(SignMethod method);
// Parses "automatic", "pseudonormal", "winding" or "paper".
std::optional<SignMethod> parse_sign_method(std::string_view name);

}  // namespace ncv
