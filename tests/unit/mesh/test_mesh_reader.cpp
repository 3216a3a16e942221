// Mesh input: every format detected by content, welded, and every fault refused clearly.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "mesh/mesh_reader.hpp"
#include "util/error.hpp"

using namespace ncv;

namespace {

// A binary STL of a tetrahedron (4 triangles, 4 distinct corners), header text given.
std::vector<char> binary_tetrahedron(const std::string& header_text, float poison = 0.0f) {
  const float v[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  std::vector<char> bytes(84 + 4 * 50, 0);
  std::memcpy(bytes.data(), header_text.data(), std::min<std::size_t>(80, header_text.size()));
  const std::uint32_t count = 4;
  std::memcpy(bytes.data() + 80, &count, 4);
  for (int f = 0; f < 4; ++f) {
    for (int k = 0; k < 3; ++k) {
      float p[3] = {v[faces[f][k]][0], v[faces[f][k]][1], v[faces[f][k]][2]};
      if (f == 3 && k == 2) p[1] += poison;
      std::memcpy(bytes.data() + 84 + 50 * f + 12 + 12 * k, p, 12);
    }
  }
  return bytes;
}

std::vector<char> text(const std::string& s) {
  return {s.begin(), s.end()};
}

const char* kAsciiTetrahedron = R"(solid tet
facet normal 0 0 -1
 outer loop
  vertex 0 0 0
  vertex 0 1 0
  vertex 1 0 0
 endloop
endfacet
facet normal 0 -1 0
 outer loop
  vertex 0 0 0
  vertex 1 0 0
  vertex 0 0 1
 endloop
endfacet
facet normal -1 0 0
 outer loop
  vertex 0 0 0
  vertex 0 0 1
  vertex 0 1 0
 endloop
endfacet
facet normal 1 1 1
 outer loop
  vertex 1 0 0
  vertex 0 1 0
  vertex 0 0 1
 endloop
endfacet
endsolid tet
)";

std::string refusal(const std::vector<char>& bytes) {
  try {
    parse_mesh(bytes, "part.stl");
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

}  // namespace

TEST_CASE("binary STL is welded, even when its header starts with 'solid'", "[mesh-reader]") {
  for (const std::string header : {"binary", "solid lying header"}) {
    MeshReadReport report;
    const Mesh mesh = parse_mesh(binary_tetrahedron(header), "tet.stl", &report);
    CHECK(report.format == MeshFormat::stl_binary);
    CHECK(mesh.vertex_count() == 4);
    CHECK(mesh.triangle_count() == 4);
    CHECK(surface_area(mesh) == Approx(1.5 + std::sqrt(3.0) / 2));
  }
}

TEST_CASE("ASCII STL, OFF, OBJ and PLY give the same tetrahedron", "[mesh-reader]") {
  const std::string off =
      "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  const std::string obj =
      "# tet\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  const std::pair<std::string, MeshFormat> cases[] = {{kAsciiTetrahedron, MeshFormat::stl_ascii},
                                                      {off, MeshFormat::off},
                                                      {obj, MeshFormat::obj},
                                                      {ply, MeshFormat::ply}};
  for (const auto& [content, format] : cases) {
    INFO(format_name(format));
    MeshReadReport report;
    const Mesh mesh = parse_mesh(text(content), "tet", &report);
    CHECK(report.format == format);
    CHECK(mesh.vertex_count() == 4);
    CHECK(mesh.triangle_count() == 4);
    CHECK(surface_area(mesh) == Approx(1.5 + std::sqrt(3.0) / 2));
  }
}

TEST_CASE("broken and foreign files get one clear error", "[mesh-reader]") {
  CHECK_THAT(refusal({}), Catch::Contains("empty"));
  std::vector<char> no_triangles(84, 0);
  CHECK_THAT(refusal(no_triangles), Catch::Contains("no triangles"));

  std::vector<char> cut = binary_tetrahedron("binary");
  cut.resize(84 + 50 + 20);
  CHECK_THAT(refusal(cut), Catch::Contains("claims 4 triangles"));

  std::vector<char> huge(1024, 1);
  const std::uint32_t claimed = 2'000'000'000u;
  std::memcpy(huge.data() + 80, &claimed, 4);
  CHECK_THAT(refusal(huge), Catch::Contains("claims 2000000000 triangles"));

  CHECK_THAT(refusal(text("solid x\nthis is not an STL at all\n")), Catch::Contains("line 2"));
  CHECK_THAT(refusal(text(std::string(kAsciiTetrahedron).substr(0, 200))),
             Catch::Contains("truncated"));

  std::vector<char> png = text("\x89PNG\r\n\x1a\n");
  png.resize(300, 7);
  CHECK_THAT(refusal(png), Catch::Contains("PNG image"));
  CHECK_THAT(refusal(text("hello world, just some words\n")), Catch::Contains("not a mesh"));

  CHECK_THAT(refusal(binary_tetrahedron("binary", std::numeric_limits<float>::quiet_NaN())),
             Catch::Contains("NaN"));
  CHECK_THAT(refusal(binary_tetrahedron("binary", std::numeric_limits<float>::infinity())),
             Catch::Contains("infinite"));
  std::string nan_ascii = kAsciiTetrahedron;
  nan_ascii.replace(nan_ascii.find("vertex 0 1 0"), 12, "vertex 0 nan 0");
  CHECK_THAT(refusal(text(nan_ascii)), Catch::Contains("NaN"));
}

TEST_CASE("degenerate triangles are counted", "[mesh-reader]") {
  const std::string off = "OFF\n4 2 0\n0 0 0\n1 0 0\n2 0 0\n0 1 0\n3 0 1 2\n3 0 1 3\n";
  MeshReadReport report;
  const Mesh mesh = parse_mesh(text(off), "flat.off", &report);
  CHECK(mesh.triangle_count() == 2);
  CHECK(report.degenerate_triangles == 1);
}
