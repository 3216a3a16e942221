#include "mesh/vertex_welder.hpp"

#include <algorithm>
#include <bit>
#include <cstring>

namespace ncv {
namespace {

std::array<std::uint64_t, 3> coordinate_bits(Vec3 p) {
  std::array<std::uint64_t, 3> bits;
  for (int k = 0; k < 3; ++k) {
    const double value = p[k] + 0.0;  // -0 and +0 are one point
    std::memcpy(&bits[k], &value, sizeof value);
  }
  return bits;
}

std::size_t hash_bits(const std::array<std::uint64_t, 3>& bits) {
  std::uint64_t h = (bits[0] ^ (bits[0] >> 32)) * 0x9E3779B97F4A7C15ull;
  h ^= (h >> 29) ^ ((bits[1] ^ (bits[1] >> 32)) * 0xC2B2AE3D27D4EB4Full);
  h ^= (h >> 31) ^ ((bits[2] ^ (bits[2] >> 32)) * 0x165667B19E3779F9ull);
  return static_cast<std::size_t>(h ^ (h >> 32));
}

}  // namespace

VertexWelder::VertexWelder(std::size_t expected_vertices) {
  const std::size_t capacity = std::bit_ceil(std::max<std::size_t>(16, 2 * expected_vertices));
  slots_.assign(capacity, 0);
  mask_ = capacity - 1;
  keys_.reserve(expected_vertices);
  vertices_.reserve(expected_vertices);
}

std::uint32_t VertexWelder::weld(Vec3 p) {
  const auto bits = coordinate_bits(p);
  for (std::size_t slot = hash_bits(bits) & mask_;; slot = (slot + 1) & mask_) {
    const std::uint32_t entry = slots_[slot];
    if (entry == 0) {
      const auto index = static_cast<std::uint32_t>(vertices_.size());
      slots_[slot] = index + 1;
      keys_.push_back(bits);
      vertices_.push_back(p);
      if (2 * vertices_.size() > slots_.size()) grow();
      return index;
    }
    const auto& key = keys_[entry - 1];
    if (key[0] == bits[0] && key[1] == bits[1] && key[2] == bits[2]) return entry - 1;
  }
}

void VertexWelder::grow() {
  slots_.assign(2 * slots_.size(), 0);
  mask_ = slots_.size() - 1;
  for (std::size_t v = 0; v < keys_.size(); ++v) {
    std::size_t slot = hash_bits(keys_[v]) & mask_;
    while (slots_[slot] != 0) slot = (slot + 1) & mask_;
    slots_[slot] = static_cast<std::uint32_t>(v + 1);
  }
}

}  // namespace ncv
