// PLY, OFF and OBJ read by ncverify itself: double precision kept, every variant users
// meet accepted, and every fault (including those that hung or misled OpenMesh) refused
// with one clear message.
#include <catch2/catch.hpp>

#include <cstring>
#include <string>
#include <vector>

#include "mesh/mesh_reader.hpp"
#include "mesh/polygon_reader.hpp"
#include "util/error.hpp"

using namespace ncv;

namespace {

std::vector<char> bytes(const std::string& text) {
  return {text.begin(), text.end()};
}

std::string refusal(const std::string& content) {
  try {
    parse_mesh(bytes(content), "part");
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

const std::string kPlyHeader =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
    "property double z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n";
const std::string kPlyFaces = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

// A binary PLY tetrahedron of doubles, in either byte order.
std::vector<char> binary_ply(bool big_endian, double x0) {
  std::string text = std::string("ply\nformat ") +
                     (big_endian ? "binary_big_endian" : "binary_little_endian") +
                     " 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
                     "property double z\nelement face 4\n"
                     "property list uchar int vertex_indices\nend_header\n";
  std::vector<char> out(text.begin(), text.end());
  auto put = [&](const void* data, std::size_t n) {
    const auto* p = static_cast<const char*>(data);
    for (std::size_t k = 0; k < n; ++k) out.push_back(p[big_endian ? n - 1 - k : k]);
  };
  const double v[4][3] = {{x0, 0, 0}, {x0 + 1, 0, 0}, {x0, 1, 0}, {x0, 0, 1}};
  for (const auto& p : v) {
    for (double c : p) put(&c, 8);
  }
  const std::int32_t f[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  for (const auto& t : f) {
    out.push_back(3);
    for (std::int32_t i : t) put(&i, 4);
  }
  return out;
}

}  // namespace

TEST_CASE("coordinates keep double precision in every polygon format", "[polygon-reader]") {
  // 1000000.001 as a float is 1000000: OpenMesh lost the millimetre's thousandths.
  const double far = 1000000.001;
  const std::string p = "1000000.001";
  const std::string ply =
      kPlyHeader + p + " 0 0\n1000001.001 0 0\n" + p + " 1 0\n" + p + " 0 1\n" + kPlyFaces;
  const std::string off = "OFF\n4 4 0\n" + p + " 0 0\n1000001.001 0 0\n" + p + " 1 0\n" + p +
                          " 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  const std::string obj = "v " + p + " 0 0\nv 1000001.001 0 0\nv " + p + " 1 0\nv " + p +
                          " 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  for (const std::vector<char>& content :
       {bytes(ply), bytes(off), bytes(obj), binary_ply(false, far), binary_ply(true, far)}) {
    const Mesh mesh = parse_mesh(content, "far");
    REQUIRE(mesh.vertex_count() == 4);
    CHECK(mesh.vertices[0][0] == far);
    CHECK(mesh.triangle_count() == 4);
  }
}

TEST_CASE("polygon variants users meet are read", "[polygon-reader]") {
  SECTION("PLY with extra properties, other elements, CRLF line ends and a quad") {
    const std::string ply =
        "ply\r\nformat ascii 1.0\r\ncomment made by hand\r\nelement vertex 4\r\n"
        "property float x\r\nproperty float y\r\nproperty float z\r\nproperty float nx\r\n"
        "property uchar red\r\nelement face 1\r\nproperty list uchar uint vertex_index\r\n"
        "property uchar flags\r\nelement edge 1\r\nproperty int vertex1\r\n"
        "property int vertex2\r\nend_header\r\n"
        "0 0 0 nan 255\r\n1 0 0 0 0\r\n1 1 0 0 0\r\n0 1 0 0 0\r\n4 0 1 2 3 7\r\n0 1\r\n";
    const Mesh mesh = parse_ply(bytes(ply), "quad.ply");
    CHECK(mesh.vertex_count() == 4);
    REQUIRE(mesh.triangle_count() == 2);  // fan: (0,1,2), (0,2,3)
    CHECK(mesh.triangles[1] == Triangle{0, 2, 3});
  }
  SECTION("OFF with counts on the keyword line, comments and face colours") {
    const std::string off =
        "# a tetrahedron\nCOFF 4 4 6\n0 0 0 255 0 0 255\n1 0 0 0 0 0 255\n0 1 0 0 0 0 255\n"
        "0 0 1 0 0 0 255 # apex\n3 0 2 1 1 0 0\n3 0 1 3\n3 0 3 2\n3 1 2 3\n\n";
    const Mesh mesh = parse_off(bytes(off), "tet.off");
    CHECK(mesh.vertex_count() == 4);
    CHECK(mesh.triangle_count() == 4);
  }
  SECTION("OBJ with texture and normal indices, negative indices and other statements") {
    const std::string obj =
        "mtllib part.mtl\no part\nv 0 0 0\nv 1 0 0\nv 1 1 0 0.5 0.5 0.5\nv 0 1 0\nvt 0 0\n"
        "vn 0 0 1\ng top\nusemtl steel\ns off\nf 1/1/1 2/1/1 3//1\nf -4 -2 -1\n";
    const Mesh mesh = parse_obj(bytes(obj), "part.obj");
    CHECK(mesh.vertex_count() == 4);
    REQUIRE(mesh.triangle_count() == 2);
    CHECK(mesh.triangles[1] == Triangle{0, 2, 3});
  }
}

TEST_CASE("malformed polygon files are refused with one clear message", "[polygon-reader]") {
  // The first hung OpenMesh forever (found by fuzz_mesh): its header reader waits for an
  // end_header that never comes.
  CHECK_THAT(refusal("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nend_headEr\n"),
             Catch::Contains("unexpected header line"));
  CHECK_THAT(refusal("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"),
             Catch::Contains("no end_header"));
  CHECK_THAT(refusal("ply\nformat binary_middle_endian 1.0\nend_header\n"),
             Catch::Contains("unknown format"));
  CHECK_THAT(refusal(kPlyHeader + "0 0 0\n1 0 0\n0 1 0\n"),
             Catch::Contains("element 'vertex' claims 4 items, the data ends after 3"));
  CHECK_THAT(
      refusal(kPlyHeader + "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 9\n3 0 3 2\n3 1 2 3\n"),
      Catch::Contains("refers to vertex 9, but there are 4 vertices"));
  CHECK_THAT(refusal(kPlyHeader + "0 0 0\n1 0 0\n0 1 0\n0 0 1\n2 0 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"),
             Catch::Contains("face 0: a face has 2 corners"));
  CHECK_THAT(refusal(kPlyHeader + "0 0 0\n1 0 zero\n"), Catch::Contains("'zero' is not a number"));
  CHECK_THAT(refusal(kPlyHeader + "0 0 0\n1 0 inf\n"), Catch::Contains("vertex 1 has a NaN"));
  // Finite but beyond what distances can square: a workpiece like this used to reach
  // sampling with a step of "inf".
  CHECK_THAT(refusal(kPlyHeader + "0 0 0\n1e200 0 0\n0 1 0\n0 0 1\n" + kPlyFaces),
             Catch::Contains("part: a vertex lies beyond 1e+100"));
  CHECK_THAT(refusal(kPlyHeader + "0 0 0\n1 0 0\n0 1 0\n0 0 1\n" + kPlyFaces + "3 1 2 3\n"),
             Catch::Contains("after the last element"));
  // Counts far beyond the data: refused as truncated, no memory reserved for them.
  CHECK_THAT(refusal("ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n"
                     "property float x\nproperty float y\nproperty float z\nend_header\n1234"),
             Catch::Contains("data ends early"));
  std::vector<char> huge_list = binary_ply(false, 0);
  huge_list[huge_list.size() - 13] = static_cast<char>(255);  // the last face's corner count
  CHECK_THROWS_WITH(parse_mesh(huge_list, "list.ply"), Catch::Contains("a list claims 255 values"));

  CHECK_THAT(refusal("OFF\n2000000000 3000000000 0\n0 0 0\n"),
             Catch::Contains("OFF, line 3: the file ends before the last vertex"));
  CHECK_THAT(refusal("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4000000000 0 1 2\n"),
             Catch::Contains("fewer than its 4000000000 corners"));
  CHECK_THAT(refusal("OFF BINARY\n"), Catch::Contains("binary OFF is not supported"));
  CHECK_THAT(refusal("4OFF\n"), Catch::Contains("other than three coordinates"));
  CHECK_THAT(refusal("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n"),
             Catch::Contains("after the last face"));
  CHECK_THAT(refusal("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1e999 0\n3 0 1 2\n"),
             Catch::Contains("NaN, infinite or out of range"));

  CHECK_THAT(refusal("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n"), Catch::Contains("'0' is not"));
  CHECK_THAT(refusal("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n"),
             Catch::Contains("counts back past the first vertex"));
  CHECK_THAT(refusal("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"),
             Catch::Contains("refers to vertex 3, but there are 3 vertices"));
  CHECK_THAT(refusal("v 0 0 0\nv 1 0 0\nv 0 1\nf 1 2 3\n"),
             Catch::Contains("OBJ, line 3: a vertex has fewer than three coordinates"));
  CHECK_THAT(refusal("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 \\\n 3\n"),
             Catch::Contains("line continuations"));
}
