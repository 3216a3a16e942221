#include "ncgen/stl_writer.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace ncv::gen {
namespace {

constexpr std::size_t header_bytes = 80;
constexpr std::size_t record_bytes = 50;

void put_vec3(Vec3 v, char* out) {
  const std::array<float, 3> f{static_cast<float>(v[0]), static_cast<float>(v[1]),
                               static_cast<float>(v[2])};
  std::memcpy(out, f.data(), sizeof f);
}

void put_record(const ncv::Mesh& mesh, std::size_t t, char* out) {
  put_vec3(normalized(area_vector(mesh, t)), out);
  for (int k = 0; k < 3; ++k) put_vec3(mesh.corner(t, k), out + 12 * (k + 1));
  std::memset(out + 48, 0, 2);
}

}  // namespace

void write_binary_stl(const ncv::Mesh& mesh, const std::filesystem::path& path,
                      std::string_view header) {
  static_assert(std::endian::native == std::endian::little, "STL is little-endian");
  std::ofstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error("cannot create " + path.string());

  std::array<char, header_bytes> head{};
  std::copy_n(header.begin(), std::min(header.size(), header_bytes), head.begin());
  const auto count = static_cast<std::uint32_t>(mesh.triangle_count());
  file.write(head.data(), header_bytes);
  file.write(reinterpret_cast<const char*>(&count), sizeof count);

  // Buffered in blocks: one write per triangle would dominate for a million of them.
  constexpr std::size_t block = 1 << 14;
  std::vector<char> buffer(block * record_bytes);
  for (std::size_t first = 0; first < mesh.triangle_count(); first += block) {
    const std::size_t n = std::min(block, mesh.triangle_count() - first);
    for (std::size_t t = 0; t < n; ++t) put_record(mesh, first + t, &buffer[t * record_bytes]);
    file.write(buffer.data(), static_cast<std::streamsize>(n * record_bytes));
  }
  if (!file) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace ncv::gen
