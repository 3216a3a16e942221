#include "ply_writer.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>

#include <fmt/format.h>

#include "error.hpp"

namespace ncv {

namespace {

constexpr std::size_t kFlushBytes = 1 << 20;

// Byte-wise little-endian output, independent of the host's byte order.
class LittleEndianBuffer {
 public:
  explicit LittleEndianBuffer(std::ostream& out) : out_(out) { bytes_.reserve(kFlushBytes + 64); }

  void put_u8(std::uint8_t value) { bytes_.push_back(static_cast<char>(value)); }
  void put_u32(std::uint32_t value) {
    for (int shift = 0; shift < 32; shift += 8) put_u8(static_cast<std::uint8_t>(value >> shift));
  }
  void put_float(double value) { put_u32(std::bit_cast<std::uint32_t>(static_cast<float>(value))); }

  void flush_if_full() {
    if (bytes_.size() >= kFlushBytes) flush();
  }
  void flush() {
    out_.write(bytes_.data(), static_cast<std::streamsize>(bytes_.size()));
    bytes_.clear();
  }

 private:
  std::ostream& out_;
  std::string bytes_;
};

std::string single_line(std::string text) {
  std::replace_if(
      text.begin(), text.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
  return text;
}

void write_header(std::ostream& out, const ErrorMesh& mesh, const ColorMap& map,
                  std::span<const std::string> comments) {
  out << "ply\nformat binary_little_endian 1.0\n";
  for (const std::string& comment : comments) out << "comment " << single_line(comment) << '\n';
  out << "comment " << single_line(map.description()) << '\n';
  out << fmt::format("element vertex {}\n", mesh.mesh.vertex_count())
      << "property float x\nproperty float y\nproperty float z\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\n"
      << "property float quality\nproperty float scalar_signed_distance\n"
      << fmt::format("element face {}\n", mesh.mesh.triangle_count())
      << "property list uchar int vertex_indices\nend_header\n";
}

}  // namespace

void write_error_ply(std::ostream& out, const ErrorMesh& mesh, const ColorMap& map,
                     std::span<const std::string> comments) {
  if (mesh.mesh.vertex_count() > std::uint64_t{std::numeric_limits<std::int32_t>::max()}) {
    throw UsageError(fmt::format("{} vertices are too many for PLY int vertex indices",
                                 mesh.mesh.vertex_count()));
  }
  write_header(out, mesh, map, comments);
  LittleEndianBuffer buffer(out);
  for (std::size_t v = 0; v < mesh.mesh.vertex_count(); ++v) {
    const Vec3 p = mesh.mesh.vertices[v];
    buffer.put_float(p.x);
    buffer.put_float(p.y);
    buffer.put_float(p.z);
    for (const std::uint8_t channel : map.rgb(mesh.values[v])) buffer.put_u8(channel);
    buffer.put_float(mesh.values[v]);
    buffer.put_float(mesh.values[v]);
    buffer.flush_if_full();
  }
  for (const Triangle& triangle : mesh.mesh.triangles) {
    buffer.put_u8(3);
    for (const std::uint32_t index : triangle) buffer.put_u32(index);
    buffer.flush_if_full();
  }
  buffer.flush();
}

}  // namespace ncv
