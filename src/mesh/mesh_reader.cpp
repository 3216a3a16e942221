#include "mesh/mesh_reader.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string_view>

#include "mesh/polygon_reader.hpp"
#include "mesh/stl_reader.hpp"
#include "mesh/vertex_order.hpp"
#include "util/error.hpp"
#include "util/input_bytes.hpp"

namespace ncv {
namespace {

std::string_view leading_text(std::span<const char> bytes, std::size_t length) {
  return {bytes.data(), std::min(length, bytes.size())};
}

bool starts_with(std::span<const char> bytes, std::string_view prefix) {
  return leading_text(bytes, prefix.size()) == prefix;
}

bool is_text(std::span<const char> bytes) {
  const std::size_t probe = std::min<std::size_t>(bytes.size(), 4096);
  return std::none_of(
      bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(probe), [](char c) {
        const auto u = static_cast<unsigned char>(c);
        return u == 0 || (u < 32 && u != '\n' && u != '\r' && u != '\t' && u != '\f' && u != '\v');
      });
}

bool looks_like_off(std::span<const char> bytes) {
  std::string_view head = leading_text(bytes, 16);
  head.remove_prefix(std::min(head.find_first_not_of(" \t\r\n"), head.size()));
  for (std::string_view tag : {"OFF", "COFF", "NOFF", "CNOFF", "STOFF", "4OFF", "nOFF"}) {
    if (head.substr(0, tag.size()) == tag) return true;
  }
  return false;
}

bool looks_like_obj(std::span<const char> bytes) {
  if (!is_text(bytes)) return false;
  const std::string_view text(bytes.data(), bytes.size());
  return (text.starts_with("v ") || text.find("\nv ") != std::string_view::npos) &&
         (text.find("\nf ") != std::string_view::npos);
}

// Recognisable non-mesh files get a precise message instead of a parse error.
std::string known_non_mesh(std::span<const char> bytes) {
  if (starts_with(bytes, "\x89PNG")) return "a PNG image";
  if (starts_with(bytes, "\xFF\xD8\xFF")) return "a JPEG image";
  if (starts_with(bytes, "%PDF")) return "a PDF document";
  if (starts_with(bytes, "PK\x03\x04")) return "a ZIP archive";
  if (starts_with(bytes, "\x1F\x8B")) return "a gzip archive";
  if (starts_with(bytes, "NCVERIFY")) return "an ncverify intermediate file";
  return {};
}

Mesh parse_by_content(std::span<const char> bytes, const std::string& source,
                      MeshReadReport& report) {
  if (bytes.empty()) throw InputError(source, "empty file, expected a mesh");
  if (looks_like_binary_stl(bytes)) {
    report.format = MeshFormat::stl_binary;
    return parse_binary_stl(bytes, source);
  }
  if (const std::string what = known_non_mesh(bytes); !what.empty()) {
    throw InputError(source, "is " + what + ", not a mesh (STL, PLY, OBJ or OFF)");
  }
  if (looks_like_ascii_stl(bytes) && is_text(bytes)) {
    report.format = MeshFormat::stl_ascii;
    return parse_ascii_stl(bytes, source);
  }
  if (starts_with(bytes, "ply")) {
    report.format = MeshFormat::ply;
    return parse_ply(bytes, source);
  }
  if (looks_like_off(bytes)) {
    report.format = MeshFormat::off;
    return parse_off(bytes, source);
  }
  if (looks_like_obj(bytes)) {
    report.format = MeshFormat::obj;
    return parse_obj(bytes, source);
  }
  if (!is_text(bytes) && bytes.size() >= 84) {
    report.format = MeshFormat::stl_binary;
    return parse_binary_stl(bytes, source);  // reports the size mismatch precisely
  }
  throw InputError(source, "not a mesh file: not recognised as STL, PLY, OBJ or OFF");
}

}  // namespace

std::string format_name(MeshFormat format) {
  switch (format) {
    case MeshFormat::stl_binary:
      return "binary STL";
    case MeshFormat::stl_ascii:
      return "ASCII STL";
    case MeshFormat::ply:
      return "PLY";
    case MeshFormat::obj:
      return "OBJ";
    case MeshFormat::off:
      return "OFF";
  }
  return "unknown";
}

Mesh parse_mesh(std::span<const char> bytes, const std::string& source, MeshReadReport* report) {
  MeshReadReport local;
  MeshReadReport& r = report ? *report : local;
  r = {};
  Mesh mesh = parse_by_content(bytes, source, r);
  check_mesh(mesh, source);
  if (vertices_scattered(mesh)) order_vertices_spatially(mesh);
  r.degenerate_triangles = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, mesh.triangle_count(), 1 << 14), std::size_t{0},
      [&](const tbb::blocked_range<std::size_t>& range, std::size_t degenerate) {
        for (std::size_t t = range.begin(); t < range.end(); ++t) {
          if (squared_norm(area_vector(mesh, t)) == 0) ++degenerate;
        }
        return degenerate;
      },
      std::plus<>());
  return mesh;
}

Mesh read_mesh(const std::string& path) {
  const InputBytes bytes = read_input_bytes(path);
  MeshReadReport report;
  Mesh mesh = parse_mesh(bytes.span(), input_name(path), &report);
  spdlog::debug("read {}: {}, {} vertices, {} triangles ({} of zero area)", input_name(path),
                format_name(report.format), mesh.vertex_count(), mesh.triangle_count(),
                report.degenerate_triangles);
  return mesh;
}

}  // namespace ncv
