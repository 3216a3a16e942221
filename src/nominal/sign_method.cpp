#include "nominal/sign_method.hpp"

#include <array>

namespace ncv {
namespace {

constexpr std::array<std::string_view, 4> kNames = {"automatic", "pseudonormal", "winding",
                                                    "paper"};

}  // namespace

std::string_view sign_method_name(SignMethod method) {
  const auto index = static_cast<std::size_t>(method);
  return index < kNames.size() ? kNames[index] : std::string_view("unknown");
}

std::optional<SignMethod> parse_sign_method(std::string_view name) {
  for (std::size_t i = 0; i < kNames.size(); ++i) {
    if (kNames[i] == name) return static_cast<SignMethod>(i);
  }
  return std::nullopt;
}

}  // namespace ncv
