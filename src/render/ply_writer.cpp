#include "render/ply_writer.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "util/error.hpp"

namespace ncv {

namespace {

constexpr std::size_t kVertexBytes = 3 * 4 + 3 + 2 * 4 + 4;
constexpr std::size_t kFaceBytes = 1 + 3 * 4;

// Little-endian fields at a byte position, independent of the host's byte order.
char* put_u32(char* at, std::uint32_t value) {
  for (int shift = 0; shift < 32; shift += 8) *at++ = static_cast<char>(value >> shift);
  return at;
}

char* put_float(char* at, double value) {
  return put_u32(at, std::bit_cast<std::uint32_t>(static_cast<float>(value)));
}

std::string single_line(std::string text) {
  std::replace_if(
      text.begin(), text.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
  return text;
}

std::string header(const ErrorMesh& mesh, const ColorMap& map,
                   std::span<const std::string> comments) {
  std::string text = "ply\nformat binary_little_endian 1.0\n";
  for (const std::string& comment : comments) text += "comment " + single_line(comment) + '\n';
  text += "comment " + single_line(map.description()) + '\n';
  text += fmt::format("element vertex {}\n", mesh.mesh.vertex_count());
  text +=
      "property float x\nproperty float y\nproperty float z\n"
      "property uchar red\nproperty uchar green\nproperty uchar blue\n"
      "property float quality\nproperty float scalar_signed_distance\nproperty int scalar_region\n";
  text += fmt::format("element face {}\n", mesh.mesh.triangle_count());
  text += "property list uchar int vertex_indices\nend_header\n";
  return text;
}

void put_vertex(char* at, Vec3 p, const Rgb& rgb, double value, std::uint32_t region) {
  at = put_float(at, p[0]);
  at = put_float(at, p[1]);
  at = put_float(at, p[2]);
  for (const std::uint8_t channel : rgb) *at++ = static_cast<char>(channel);
  at = put_float(at, value);
  at = put_float(at, value);
  put_u32(at, region);
}

void put_face(char* at, const Triangle& triangle) {
  *at++ = 3;
  for (const std::uint32_t index : triangle) at = put_u32(at, index);
}

}  // namespace

Buffer<char> error_ply(const ErrorMesh& mesh, const ColorMap& map,
                       std::span<const std::string> comments) {
  const std::size_t vertices = mesh.mesh.vertex_count();
  const std::size_t faces = mesh.mesh.triangle_count();
  if (vertices > std::uint64_t{std::numeric_limits<std::int32_t>::max()}) {
    throw UsageError(fmt::format("{} vertices are too many for PLY int vertex indices", vertices));
  }
  const std::string head = header(mesh, map, comments);
  Buffer<char> bytes(head.size() + vertices * kVertexBytes + faces * kFaceBytes);
  std::copy(head.begin(), head.end(), bytes.begin());
  char* const vertex_records = bytes.data() + head.size();
  char* const face_records = vertex_records + vertices * kVertexBytes;
  // Fixed-size records: every range fills its own bytes.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vertices, 1 << 14),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t v = range.begin(); v != range.end(); ++v) {
                        put_vertex(vertex_records + v * kVertexBytes, mesh.mesh.vertices[v],
                                   map.rgb(mesh.values[v]), mesh.values[v], mesh.regions[v]);
                      }
                    });
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, faces, 1 << 15),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t f = range.begin(); f != range.end(); ++f)
                        put_face(face_records + f * kFaceBytes, mesh.mesh.triangles[f]);
                    });
  return bytes;
}

}  // namespace ncv
