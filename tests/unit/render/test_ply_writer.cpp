#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <unistd.h>

// OpenMesh's VectorT leaves its default-constructed elements uninitialised by design, and
// GCC flags the colour property's instantiation of that here.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include "render/color_map.hpp"
#include "render/error_mesh.hpp"
#include "render/ply_writer.hpp"
#include "sampling/lattice_triangles.hpp"
#include "sampling/sampling.hpp"
#include "statistics/error_regions.hpp"
#include "stats_fixtures.hpp"
#include "util/output_file.hpp"

using ncv::ErrorMesh;
using ncv::SampleSet;
using ncv::Vec3;

namespace {

namespace fs = std::filesystem;
using OpenMeshTriMesh = OpenMesh::TriMesh_ArrayKernelT<>;

constexpr std::size_t kVertexBytes = 3 * 4 + 3 + 2 * 4 + 4;

struct PlyFile {
  std::vector<std::string> header;  // lines up to and including end_header
  std::string body;                 // the binary part
};

PlyFile split(const std::string& bytes) {
  PlyFile file;
  std::size_t begin = 0;
  for (;;) {
    const std::size_t end = bytes.find('\n', begin);
    REQUIRE(end != std::string::npos);
    file.header.push_back(bytes.substr(begin, end - begin));
    begin = end + 1;
    if (file.header.back() == "end_header") break;
  }
  file.body = bytes.substr(begin);
  return file;
}

std::uint32_t u32_at(const std::string& body, std::size_t offset) {
  std::uint32_t bits = 0;
  for (int k = 3; k >= 0; --k) bits = bits << 8 | static_cast<unsigned char>(body[offset + k]);
  return bits;
}

float float_at(const std::string& body, std::size_t offset) {
  return std::bit_cast<float>(u32_at(body, offset));
}

std::int32_t int_at(const std::string& body, std::size_t offset) {
  return static_cast<std::int32_t>(u32_at(body, offset));
}

fs::path temporary_ply() {
  return fs::temp_directory_path() / ("ncverify-ply-test-" + std::to_string(::getpid()) + ".ply");
}

std::string to_ply(const ncv::PlyMesh& mesh, const ncv::ColorMap& map) {
  const std::vector<std::string> comments = {"ncverify test", "two\nlines"};
  const fs::path path = temporary_ply();
  ncv::OutputFile out(path.string(), ncv::OutputKind::binary);
  ncv::write_error_ply(out, mesh, map, comments);
  out.commit();
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  fs::remove(path);
  return bytes;
}

std::string to_ply(const ErrorMesh& mesh, const ncv::ColorMap& map) {
  return to_ply(ncv::ErrorMeshPly(mesh), map);
}

// Reads the file back with OpenMesh, as MeshLab-style tools would.
OpenMeshTriMesh read_back(const std::string& bytes) {
  const fs::path path = temporary_ply();
  std::ofstream(path, std::ios::binary) << bytes;
  OpenMeshTriMesh mesh;
  mesh.request_vertex_colors();
  OpenMesh::IO::Options options = OpenMesh::IO::Options::VertexColor;
  const bool read = OpenMesh::IO::read_mesh(mesh, path.string(), options);
  fs::remove(path);
  REQUIRE(read);
  CHECK(options.check(OpenMesh::IO::Options::VertexColor));
  return mesh;
}

// The samples of a 2x2-cell square with lattice size 3, and d = x - 0.5: gouge at x = 0,
// within at x = 0.5, excess at x = 1 for the zone +-0.25.
SampleSet square_samples(ncv::SamplingScheme scheme = ncv::SamplingScheme::all) {
  return ncv::sample_mesh(ncv::test::flat_grid(2, 1.0), 0.2, scheme);
}

const ncv::ColorMap kMap =
    ncv::make_color_map(ncv::ColorMapKind::tolerance, {-0.5, 0.5}, ncv::Tolerance{-0.25, 0.25});

}  // namespace

TEST_CASE("the PLY header declares the documented layout", "[ply]") {
  const SampleSet samples = square_samples();
  const auto d = ncv::test::distances_of(samples, [](Vec3 p) { return p[0] - 0.5; });
  const ErrorMesh mesh = ncv::workpiece_error_mesh(samples, d);
  const PlyFile file = split(to_ply(mesh, kMap));
  const std::vector<std::string> expected = {
      "ply",
      "format binary_little_endian 1.0",
      "comment ncverify test",
      "comment two lines",
      "comment colour map tolerance over -0.5:0.5, tolerance -0.25:0.25",
      "element vertex 9",
      "property float x",
      "property float y",
      "property float z",
      "property uchar red",
      "property uchar green",
      "property uchar blue",
      "property float quality",
      "property float scalar_signed_distance",
      "property int scalar_region",
      "element face 8",
      "property list uchar int vertex_indices",
      "end_header"};
  CHECK(file.header == expected);
  CHECK(file.body.size() == 9 * kVertexBytes + 8 * 13);
}

TEST_CASE("the workpiece PLY carries positions, baked colours and signed errors", "[ply]") {
  const SampleSet samples = square_samples();
  const auto d = ncv::test::distances_of(samples, [](Vec3 p) { return p[0] - 0.5; });
  const ErrorMesh mesh = ncv::workpiece_error_mesh(samples, d);
  const std::string bytes = to_ply(mesh, kMap);
  const PlyFile file = split(bytes);

  for (std::size_t v = 0; v < mesh.mesh.vertex_count(); ++v) {
    const std::size_t at = v * kVertexBytes;
    const Vec3 p = mesh.mesh.vertices[v];
    CHECK(float_at(file.body, at) == static_cast<float>(p[0]));
    CHECK(float_at(file.body, at + 4) == static_cast<float>(p[1]));
    CHECK(float_at(file.body, at + 8) == static_cast<float>(p[2]));
    const ncv::Rgb color = kMap.rgb(p[0] - 0.5);
    CHECK(static_cast<std::uint8_t>(file.body[at + 12]) == color[0]);
    CHECK(static_cast<std::uint8_t>(file.body[at + 13]) == color[1]);
    CHECK(static_cast<std::uint8_t>(file.body[at + 14]) == color[2]);
    CHECK(float_at(file.body, at + 15) == static_cast<float>(p[0] - 0.5));
    CHECK(float_at(file.body, at + 19) == static_cast<float>(p[0] - 0.5));
  }
  const std::size_t faces = mesh.mesh.vertex_count() * kVertexBytes;
  for (std::size_t f = 0; f < mesh.mesh.triangle_count(); ++f) {
    const std::size_t at = faces + f * 13;
    CHECK(file.body[at] == 3);
    for (int k = 0; k < 3; ++k) {
      CHECK(int_at(file.body, at + 1 + 4 * k) ==
            static_cast<std::int32_t>(mesh.mesh.triangles[f][k]));
    }
  }

  const OpenMeshTriMesh read = read_back(bytes);
  REQUIRE(read.n_vertices() == 9);
  CHECK(read.n_faces() == 8);
  int classes[3] = {0, 0, 0};  // gouge, within, excess
  for (const auto vh : read.vertices()) {
    const auto point = read.point(vh);
    const auto color = read.color(vh);
    const ncv::Rgb expected = kMap.rgb(point[0] - 0.5);
    CHECK(color[0] == expected[0]);
    CHECK(color[1] == expected[1]);
    CHECK(color[2] == expected[2]);
    ++classes[static_cast<int>(ncv::classify(point[0] - 0.5, *kMap.tolerance))];
  }
  // Three vertices in each column x = 0, 0.5, 1: one of each tolerance class.
  CHECK(classes[0] == 3);
  CHECK(classes[1] == 3);
  CHECK(classes[2] == 3);
  const OpenMesh::Vec3uc green = read.color(read.vertex_handle(1));
  CHECK(green[1] > green[0]);
}

TEST_CASE("the lattice PLY shows every sample as a vertex", "[ply]") {
  const SampleSet samples =
      ncv::sample_mesh(ncv::test::flat_grid(2, 1.0), 0.1, ncv::SamplingScheme::all);
  std::uint64_t sub_triangles = 0;
  for (std::uint32_t n : samples.lattice_sizes) sub_triangles += ncv::lattice_triangle_count(n);
  REQUIRE(samples.sample_count() > 9);
  const auto d = ncv::test::distances_of(samples, [](Vec3 p) { return p[0] - 0.5; });
  const ErrorMesh mesh = ncv::lattice_error_mesh(samples, d);
  REQUIRE(mesh.mesh.vertex_count() == samples.sample_count());
  REQUIRE(mesh.mesh.triangle_count() == sub_triangles);
  const std::string bytes = to_ply(mesh, kMap);
  const PlyFile file = split(bytes);
  for (std::size_t s = 0; s < samples.sample_count(); ++s) {
    CHECK(float_at(file.body, s * kVertexBytes + 15) == static_cast<float>(d[s]));
  }
  // Every face keeps the orientation of the square (normal +z).
  for (const ncv::Triangle& t : mesh.mesh.triangles) {
    const Vec3 a = mesh.mesh.vertices[t[0]];
    CHECK(ncv::cross(mesh.mesh.vertices[t[1]] - a, mesh.mesh.vertices[t[2]] - a)[2] > 0);
  }
  const OpenMeshTriMesh read = read_back(bytes);
  CHECK(read.n_vertices() == samples.sample_count());
  CHECK(read.n_faces() == sub_triangles);
}

TEST_CASE("a PLY of many records is filled in parallel, every record in its place", "[ply]") {
  // Over 16384 vertices and 32768 faces: several ranges of the parallel fill each.
  const SampleSet samples =
      ncv::sample_mesh(ncv::test::flat_grid(2, 1.0), 0.004, ncv::SamplingScheme::all);
  const auto d = ncv::test::distances_of(samples, [](Vec3 p) { return p[0] * p[1] - 0.25; });
  const ErrorMesh mesh = ncv::lattice_error_mesh(samples, d);
  REQUIRE(mesh.mesh.vertex_count() > 3 * 16384);
  REQUIRE(mesh.mesh.triangle_count() > 3 * 32768);
  const std::string bytes = to_ply(mesh, kMap);
  const PlyFile file = split(bytes);
  REQUIRE(file.body.size() ==
          mesh.mesh.vertex_count() * kVertexBytes + mesh.mesh.triangle_count() * 13);
  for (std::size_t v = 0; v < mesh.mesh.vertex_count(); ++v) {
    const std::size_t at = v * kVertexBytes;
    REQUIRE(float_at(file.body, at) == static_cast<float>(mesh.mesh.vertices[v][0]));
    REQUIRE(float_at(file.body, at + 8) == static_cast<float>(mesh.mesh.vertices[v][2]));
    REQUIRE(static_cast<std::uint8_t>(file.body[at + 13]) == kMap.rgb(mesh.values[v])[1]);
    REQUIRE(float_at(file.body, at + 19) == static_cast<float>(mesh.values[v]));
  }
  const std::size_t faces = mesh.mesh.vertex_count() * kVertexBytes;
  for (std::size_t f = 0; f < mesh.mesh.triangle_count(); ++f) {
    REQUIRE(file.body[faces + f * 13] == 3);
    REQUIRE(int_at(file.body, faces + f * 13 + 9) ==
            static_cast<std::int32_t>(mesh.mesh.triangles[f][2]));
  }
  const OpenMeshTriMesh read = read_back(bytes);
  CHECK(read.n_vertices() == mesh.mesh.vertex_count());
  CHECK(read.n_faces() == mesh.mesh.triangle_count());
}

TEST_CASE("the lattice read in place gives the PLY of its arrays, byte for byte", "[ply]") {
  // Over 2^17 vertices and 2^18 faces, so that the writer takes several chunks of each; under
  // scheme II with unsampled slivers, whose corners are vertices after the samples.
  ncv::Mesh mesh = ncv::test::flat_grid(2, 1.0);
  const std::uint32_t base = static_cast<std::uint32_t>(mesh.vertices.size());
  for (std::uint32_t k = 0; k < 50; ++k) {
    const double x = 1.0 + 0.001 * k;
    mesh.vertices.push_back({x, 0.0, 0});
    mesh.vertices.push_back({x + 0.001, 0.0, 0});
    mesh.vertices.push_back({x, 0.0005, 0});
    mesh.triangles.push_back({base + 3 * k, base + 3 * k + 1, base + 3 * k + 2});
  }
  for (const ncv::SamplingScheme scheme :
       {ncv::SamplingScheme::all, ncv::SamplingScheme::paper_ii}) {
    const SampleSet samples = ncv::sample_mesh(mesh, 0.0015, scheme);
    const auto d = ncv::test::distances_of(samples, [](Vec3 p) { return p[0] * p[1] - 0.25; });
    const ncv::Tolerance zone{-0.1, 0.1};
    const ncv::RegionMap regions = ncv::map_error_regions(samples, d, zone);
    const ncv::LatticeMesh lattice(samples, d, regions.sample_region);
    REQUIRE(lattice.vertex_count() > std::uint64_t{3} << 17);
    REQUIRE(lattice.face_offsets().back() > std::uint64_t{3} << 18);
    if (scheme == ncv::SamplingScheme::paper_ii) {
      REQUIRE(lattice.vertex_count() > samples.sample_count());
    }
    const std::string streamed = to_ply(lattice, kMap);
    CHECK(streamed == to_ply(ncv::lattice_error_mesh(samples, d, regions.sample_region), kMap));
  }
}

TEST_CASE("vertices without a sample are grey with NaN errors", "[ply]") {
  // One large and one tiny triangle: under scheme II the tiny one is not sampled and its
  // far vertex has no sample.
  ncv::Mesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1.01, 0.01, 0}};
  mesh.triangles = {{0, 1, 2}, {1, 3, 2}};
  const SampleSet samples = ncv::sample_mesh(mesh, 0.2, ncv::SamplingScheme::paper_ii);
  REQUIRE(samples.lattice_sizes[1] == 0);
  REQUIRE(samples.vertex_sample[3] == ncv::kNoSample);
  const auto d = ncv::test::distances_of(samples, [](Vec3) { return 0.0; });

  for (const ErrorMesh& coloured :
       {ncv::workpiece_error_mesh(samples, d), ncv::lattice_error_mesh(samples, d)}) {
    std::size_t unsampled = 0;
    for (std::size_t v = 0; v < coloured.mesh.vertex_count(); ++v) {
      if (coloured.mesh.vertices[v] == Vec3{1.01, 0.01, 0}) unsampled = v;
    }
    REQUIRE(unsampled > 0);
    CHECK(std::isnan(coloured.values[unsampled]));
    const PlyFile file = split(to_ply(coloured, kMap));
    const std::size_t at = unsampled * kVertexBytes;
    CHECK(static_cast<std::uint8_t>(file.body[at + 12]) == ncv::kNoValueColor[0]);
    CHECK(static_cast<std::uint8_t>(file.body[at + 13]) == ncv::kNoValueColor[1]);
    CHECK(std::isnan(float_at(file.body, at + 15)));
    CHECK(std::isnan(float_at(file.body, at + 19)));
  }
  // The unsampled triangle stays in both meshes.
  CHECK(ncv::workpiece_error_mesh(samples, d).mesh.triangle_count() == 2);
  CHECK(ncv::lattice_error_mesh(samples, d).mesh.triangle_count() ==
        ncv::lattice_triangle_count(samples.lattice_sizes[0]) + 1);
}

TEST_CASE("every PLY vertex names its out-of-tolerance region", "[ply]") {
  // Error x - 0.5 on the unit square: with a zone of +-0.25 the band x < 0.25 is one gouge
  // region and x > 0.75 one excess region.
  const SampleSet samples =
      ncv::sample_mesh(ncv::test::flat_grid(2, 1.0), 0.1, ncv::SamplingScheme::all);
  const auto d = ncv::test::distances_of(samples, [](Vec3 p) { return p[0] - 0.5; });
  const ncv::Tolerance zone{-0.25, 0.25};
  const ncv::RegionMap regions = ncv::map_error_regions(samples, d, zone);
  REQUIRE(regions.regions.size() == 2);
  for (const ErrorMesh& mesh : {ncv::lattice_error_mesh(samples, d, regions.sample_region),
                                ncv::workpiece_error_mesh(samples, d, regions.sample_region)}) {
    const PlyFile file = split(to_ply(mesh, kMap));
    for (std::size_t v = 0; v < mesh.mesh.vertex_count(); ++v) {
      const double value = mesh.values[v];
      const std::int32_t region = int_at(file.body, v * kVertexBytes + 23);
      if (ncv::classify(value, zone) == ncv::ToleranceClass::within) {
        CHECK(region == 0);
        continue;
      }
      REQUIRE(region >= 1);
      REQUIRE(region <= 2);
      const ncv::RegionKind kind = regions.regions[region - 1].kind;
      CHECK(kind == (value > 0 ? ncv::RegionKind::excess : ncv::RegionKind::gouge));
    }
  }
  // Without a tolerance no vertex is in a region.
  const PlyFile plain = split(to_ply(ncv::lattice_error_mesh(samples, d), kMap));
  CHECK(int_at(plain.body, 23) == 0);
}
