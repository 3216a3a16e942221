#include "ncgen/part_size.hpp"

#include <charconv>
#include <stdexcept>
#include <string>

namespace ncv::gen {

double parse_size(std::string_view text) {
  if (text == "small") return small_size;
  if (text == "medium") return medium_size;
  if (text == "large") return large_size;
  double factor = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), factor);
  if (error != std::errc() || end != text.data() + text.size() || !(factor > 0) || factor > 2) {
    throw std::invalid_argument("size must be small, medium, large or a factor in (0, 2]: " +
                                std::string(text));
  }
  return factor;
}

int zmap_level(double size) {
  return size <= medium_size * 1.5 ? 9 : 10;
}

}  // namespace ncv::gen
