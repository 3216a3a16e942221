// The grid file keeps what grid-build computed of the nominal: its pseudonormals, topology
// and boundary loops come back as they were, not rebuilt, and an older grid file is refused
// with one clear line.
#include <xxhash.h>
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstring>
#include <fstream>
#include <iterator>

#include "files/grid_file.hpp"
#include "nominal_fixtures.hpp"
#include "scratch_dir.hpp"
#include "util/error.hpp"
#include "util/input_bytes.hpp"

namespace {

namespace fx = ncv::fixtures;

ncv::IndexedReference round_trip(const ncv::Mesh& mesh, const ScratchDir& dir) {
  ncv::GridStatistics statistics;
  const ncv::IndexedReference built = ncv::index_reference(mesh, "part.stl", {}, &statistics);
  const std::string path = (dir.path() / "part.grid").string();
  {
    ncv::OutputFile out(path, ncv::OutputKind::binary);
    ncv::write_grid_file(built, statistics, out);
    out.commit();
  }
  ncv::IndexedReference read = ncv::read_grid_file(path);
  const ncv::ReferenceSurface& a = *built.surface;
  const ncv::ReferenceSurface& b = *read.surface;
  CHECK(b.topology() == a.topology());
  CHECK(b.flipped() == a.flipped());
  CHECK(b.on_halfedges() == a.on_halfedges());
  CHECK(b.automatic_sign_method() == a.automatic_sign_method());
  CHECK(b.boundary_loop_count() == a.boundary_loop_count());
  REQUIRE(b.boundary_loops().size() == a.boundary_loops().size());
  for (std::size_t i = 0; i < a.boundary_loops().size(); ++i) {
    CHECK(b.boundary_loops()[i].edges == a.boundary_loops()[i].edges);
    CHECK(b.boundary_loops()[i].length == a.boundary_loops()[i].length);
    CHECK(b.boundary_loops()[i].start == a.boundary_loops()[i].start);
  }
  CHECK(std::equal(b.normals().face.begin(), b.normals().face.end(), a.normals().face.begin(),
                   a.normals().face.end()));
  CHECK(b.normals().vertex == a.normals().vertex);
  CHECK(b.normals().edge == a.normals().edge);
  CHECK(b.normals().edge_of_slot == a.normals().edge_of_slot);
  return read;
}

}  // namespace

TEST_CASE("grid file: pseudonormals, topology and loops read back as built", "[grid-file]") {
  const ScratchDir dir;
  round_trip(fx::torus(40, 10, 60, 30), dir);
  round_trip(fx::flipped(fx::box({0, 0, 0}, {1, 2, 3})), dir);
  ncv::Mesh open = fx::box({5, 5, 5}, {6, 7, 8});
  open.triangles.erase(open.triangles.begin() + 2, open.triangles.begin() + 4);
  const ncv::IndexedReference read = round_trip(open, dir);
  REQUIRE(read.surface->boundary_loop_count() == 1);
  CHECK(read.surface->boundary_loops()[0].box.min == ncv::Vec3(5, 5, 8));
  ncv::Mesh fin = fx::box({0, 0, 0}, {1, 1, 1});
  fin.vertices.push_back({0.5, -1, 0});
  fin.triangles.push_back({0, 1, 8});
  round_trip(fin, dir);
}

TEST_CASE("grid file: version 2 is refused in one line", "[grid-file]") {
  const ScratchDir dir;
  ncv::GridStatistics statistics;
  const ncv::IndexedReference built =
      ncv::index_reference(fx::box({0, 0, 0}, {1, 1, 1}), "box.stl", {}, &statistics);
  const std::string path = (dir.path() / "old.grid").string();
  {
    ncv::OutputFile out(path, ncv::OutputKind::binary);
    ncv::write_grid_file(built, statistics, out);
    out.commit();
  }
  // The reader checks the version (bytes 12 to 15) before the content hash, so an old file
  // is named as old, not as corrupt.
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::uint32_t old_version = 2;
  std::memcpy(bytes.data() + 12, &old_version, 4);
  const auto old = dir.file("old2.grid", bytes);
  try {
    ncv::read_grid_file(old.string());
    FAIL("an old grid file was read");
  } catch (const ncv::InputError& e) {
    const std::string message = e.what();
    CHECK(message.find("format version 2 is older than this ncverify reads (version 3)") !=
          std::string::npos);
    CHECK(message.find('\n') == std::string::npos);
  }
}

TEST_CASE("grid file: cell counts summing to 2^32 references or more are refused", "[grid-file]") {
  // Two cells, each listing all of a torus' 76,800 triangles (a valid grid): its counts are
  // written four bytes each, then set to 2^32 - 1 and the file sealed again.
  ncv::IndexedReference built = ncv::index_reference(fx::torus(40, 10, 320, 120), "part.stl");
  const auto triangles = static_cast<std::uint32_t>(built.mesh->triangle_count());
  REQUIRE(triangles > 65535);
  ncv::BackgroundGrid& grid = built.grid;
  grid.cell_size = 2 * grid.cell_size;
  grid.dims = {2, 1, 1};
  grid.cell_offsets = {0, triangles, 2 * triangles};
  grid.cell_triangles.resize(2 * std::size_t{triangles});
  for (std::uint32_t t = 0; t < triangles; ++t) {
    grid.cell_triangles[t] = t;
    grid.cell_triangles[triangles + t] = t;
  }
  const ScratchDir dir;
  const std::string path = (dir.path() / "part.grid").string();
  {
    ncv::OutputFile out(path, ncv::OutputKind::binary);
    ncv::write_grid_file(built, {}, out);
    out.commit();
  }
  std::ifstream in(path, std::ios::binary);
  ncv::Buffer<char> bytes;
  for (std::istreambuf_iterator<char> it(in), end; it != end; ++it) bytes.push_back(*it);
  std::uint64_t meta_bytes = 0;
  std::memcpy(&meta_bytes, bytes.data() + 16, 8);
  const nlohmann::json meta =
      nlohmann::json::parse(std::string(bytes.data() + 64, bytes.data() + 64 + meta_bytes));
  std::uint64_t offset = 0;
  for (const nlohmann::json& section : meta["sections"]) {
    if (section["name"] != "cell_counts") continue;
    REQUIRE(section["dtype"] == "<u4");
    offset = section["offset"].get<std::uint64_t>();
  }
  REQUIRE(offset > 0);
  const std::uint32_t most = 0xFFFFFFFFu;
  std::memcpy(bytes.data() + offset, &most, 4);
  std::memcpy(bytes.data() + offset + 4, &most, 4);
  const std::uint64_t hash = XXH3_64bits(bytes.data(), bytes.size() - 8);
  std::memcpy(bytes.data() + bytes.size() - 8, &hash, 8);
  CHECK_THROWS_MATCHES(
      ncv::load_indexed_reference(ncv::Container::parse(
          std::move(bytes), "x.grid", ncv::FileKind::grid, ncv::kGridFormatVersion)),
      ncv::InputError, Catch::Message("x.grid: grid has 2^32 or more references"));
}
