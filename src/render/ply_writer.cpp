#include "render/ply_writer.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <vector>

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "util/buffer.hpp"
#include "util/error.hpp"

namespace ncv {

namespace {

constexpr std::size_t kVertexBytes = 3 * 4 + 3 + 2 * 4 + 4;
constexpr std::size_t kFaceBytes = 1 + 3 * 4;
// Records per chunk: about 3.5 MB of vertices or 3.4 MB of faces, within the caches the
// kernel's copy then reads them from.
constexpr std::uint64_t kChunkVertices = std::uint64_t{1} << 17;
constexpr std::uint64_t kChunkFaces = std::uint64_t{1} << 18;

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

std::string header(std::uint64_t vertices, std::uint64_t faces, const ColorMap& map,
                   std::span<const std::string> comments) {
  std::string text = "ply\nformat binary_little_endian 1.0\n";
  for (const std::string& comment : comments) text += "comment " + single_line(comment) + '\n';
  text += "comment " + single_line(map.description()) + '\n';
  text += fmt::format("element vertex {}\n", vertices);
  text +=
      "property float x\nproperty float y\nproperty float z\n"
      "property uchar red\nproperty uchar green\nproperty uchar blue\n"
      "property float quality\nproperty float scalar_signed_distance\nproperty int scalar_region\n";
  text += fmt::format("element face {}\n", faces);
  text += "property list uchar int vertex_indices\nend_header\n";
  return text;
}

void put_vertex(char* at, const PlyVertex& v, const Rgb& rgb) {
  at = put_float(at, v.point[0]);
  at = put_float(at, v.point[1]);
  at = put_float(at, v.point[2]);
  for (const std::uint8_t channel : rgb) *at++ = static_cast<char>(channel);
  at = put_float(at, v.value);
  at = put_float(at, v.value);
  put_u32(at, v.region);
}

void put_face(char* at, const Triangle& triangle) {
  *at++ = 3;
  for (const std::uint32_t index : triangle) at = put_u32(at, index);
}

void write_vertices(OutputFile& out, const PlyMesh& mesh, const ColorMap& map,
                    Buffer<char>& bytes) {
  const std::uint64_t count = mesh.vertex_count();
  for (std::uint64_t first = 0; first < count; first += kChunkVertices) {
    const std::uint64_t end = std::min(count, first + kChunkVertices);
    bytes.resize((end - first) * kVertexBytes);
    tbb::parallel_for(tbb::blocked_range<std::uint64_t>(first, end, 1 << 12),
                      [&](const tbb::blocked_range<std::uint64_t>& range) {
                        for (std::uint64_t v = range.begin(); v != range.end(); ++v) {
                          const PlyVertex vertex = mesh.vertex(v);
                          put_vertex(bytes.data() + (v - first) * kVertexBytes, vertex,
                                     map.rgb(vertex.value));
                        }
                      });
    out.write(bytes.data(), bytes.size());
  }
}

// Whole groups per chunk: as many as fit kChunkFaces, at least one.
void write_faces(OutputFile& out, const PlyMesh& mesh, Buffer<char>& bytes) {
  const std::span<const std::uint64_t> offsets = mesh.face_offsets();
  const std::size_t groups = offsets.size() - 1;
  Buffer<Triangle> faces;
  for (std::size_t first = 0; first < groups;) {
    const auto fits = std::upper_bound(offsets.begin() + static_cast<std::ptrdiff_t>(first) + 1,
                                       offsets.end(), offsets[first] + kChunkFaces);
    const std::size_t end =
        std::max(first + 1, static_cast<std::size_t>(fits - offsets.begin()) - 1);
    const std::uint64_t base = offsets[first];
    faces.resize(offsets[end] - base);
    bytes.resize(faces.size() * kFaceBytes);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(first, end, 256),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        for (std::size_t g = range.begin(); g != range.end(); ++g) {
                          mesh.group_faces(g, faces.data() + (offsets[g] - base));
                          for (std::uint64_t f = offsets[g]; f < offsets[g + 1]; ++f) {
                            put_face(bytes.data() + (f - base) * kFaceBytes, faces[f - base]);
                          }
                        }
                      });
    out.write(bytes.data(), bytes.size());
    first = end;
  }
}

}  // namespace

void write_error_ply(OutputFile& out, const PlyMesh& mesh, const ColorMap& map,
                     std::span<const std::string> comments) {
  const std::uint64_t vertices = mesh.vertex_count();
  if (vertices > std::uint64_t{std::numeric_limits<std::int32_t>::max()}) {
    throw UsageError(fmt::format("{} vertices are too many for PLY int vertex indices", vertices));
  }
  out.write(header(vertices, mesh.face_offsets().back(), map, comments));
  Buffer<char> bytes;
  write_vertices(out, mesh, map, bytes);
  write_faces(out, mesh, bytes);
}

}  // namespace ncv
