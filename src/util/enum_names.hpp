// One name table per enum: the names users type, files store and reports print, written once
// beside the enum, e.g.
//   inline constexpr EnumName<SamplingScheme> kSamplingSchemeNames[] = {
//       {SamplingScheme::all, "all"}, {SamplingScheme::paper_ii, "paper-ii"}};
// and read by name_of, parse_name and the help text (names_list).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace ncv {

template <class E>
struct EnumName {
  E value;
  std::string_view name;
};

template <class E, std::size_t N>
constexpr std::string_view name_of(const EnumName<E> (&table)[N], E value) {
  for (const EnumName<E>& entry : table) {
    if (entry.value == value) return entry.name;
  }
  return "unknown";
}

template <class E, std::size_t N>
constexpr std::optional<E> parse_name(const EnumName<E> (&table)[N], std::string_view name) {
  for (const EnumName<E>& entry : table) {
    if (entry.name == name) return entry.value;
  }
  return std::nullopt;
}

// "a, b or c", for help texts and error messages.
template <class E, std::size_t N>
std::string names_list(const EnumName<E> (&table)[N]) {
  std::string text;
  for (std::size_t k = 0; k < N; ++k) {
    if (k > 0) text += k + 1 == N ? " or " : ", ";
    text += table[k].name;
  }
  return text;
}

}  // namespace ncv
