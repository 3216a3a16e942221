// The samples file: round trip and refusal of anything corrupted or foreign.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <random>

#include "files/samples_file.hpp"
#include "scratch_dir.hpp"
#include "util/input_bytes.hpp"

using namespace ncv;
namespace fs = std::filesystem;

namespace {

SampleSet example_set() {
  Mesh mesh{{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4}, {9, 9, 9}, {9.01, 9, 9}, {9, 9.01, 9}},
            {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {4, 5, 6}}};
  SampleSet set = sample_mesh(std::move(mesh), 0.5, SamplingScheme::paper_ii);
  set.step_spec = "0.5";
  set.source = "example.stl";
  return set;
}

fs::path write_example(const ScratchDir& dir, const SampleSet& set, const std::string& name) {
  const fs::path path = dir.path() / name;
  OutputFile out(path.string(), OutputKind::binary);
  write_samples_file(set, out);
  out.commit();
  return path;
}

std::vector<char> bytes_of(const fs::path& path) {
  const ncv::InputBytes bytes = ncv::read_input_bytes(path.string());
  return {bytes.data(), bytes.data() + bytes.size()};
}

void write_bytes(const fs::path& path, const std::vector<char>& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::string refusal(const fs::path& path) {
  try {
    read_samples_file(path.string());
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

}  // namespace

TEST_CASE("a samples file round-trips exactly", "[samples-file]") {
  const ScratchDir dir;
  const SampleSet set = example_set();
  REQUIRE(set.lattice_sizes[4] == 0);  // the tiny triangle is skipped in scheme II
  const SampleSet back = read_samples_file(write_example(dir, set, "round.samples").string());
  CHECK(back.mesh.vertices == set.mesh.vertices);
  CHECK(back.mesh.triangles == set.mesh.triangles);
  CHECK(back.mesh_hash == set.mesh_hash);
  CHECK(back.step == set.step);
  CHECK(back.step_spec == "0.5");
  CHECK(back.source == "example.stl");
  CHECK(back.scheme == SamplingScheme::paper_ii);
  CHECK(back.lattice_sizes == set.lattice_sizes);
  CHECK(back.first_interior_sample == set.first_interior_sample);
  CHECK(back.vertex_sample == set.vertex_sample);
  CHECK(back.positions == set.positions);
  CHECK(back.owner == set.owner);
  CHECK(back.lattice_i == set.lattice_i);
  CHECK(back.lattice_j == set.lattice_j);
}

TEST_CASE("sections sit at 64-byte offsets the metadata names", "[samples-file]") {
  const ScratchDir dir;
  const fs::path path = write_example(dir, example_set(), "layout.samples");
  const Container c = Container::read(path.string(), FileKind::samples, kSamplesFormatVersion);
  for (const auto& s : c.meta()["sections"]) CHECK(s["offset"].get<std::uint64_t>() % 64 == 0);
  const auto raw = c.raw_section("lattice_sizes");
  CHECK(raw.dtype == "<u1");  // the example's lattices are small: one byte each
  CHECK(raw.elements == c.count("/mesh/triangles"));
}

TEST_CASE("corrupted, truncated and foreign files are refused", "[samples-file]") {
  const ScratchDir dir;
  const fs::path good = write_example(dir, example_set(), "good.samples");
  const std::vector<char> bytes = bytes_of(good);
  const fs::path bad = dir.path() / "bad.samples";

  SECTION("a flipped byte anywhere is caught by the content hash") {
    for (std::size_t at : {std::size_t{70}, bytes.size() / 2, bytes.size() - 20}) {
      std::vector<char> flipped = bytes;
      flipped[at] ^= 0x10;
      write_bytes(bad, flipped);
      CHECK_THAT(refusal(bad), Catch::Contains("hash"));
    }
  }
  SECTION("truncation") {
    write_bytes(bad, std::vector<char>(bytes.begin(), bytes.begin() + bytes.size() / 3));
    CHECK_THAT(refusal(bad), Catch::Contains("truncated"));
    write_bytes(bad, std::vector<char>(bytes.begin(), bytes.begin() + 20));
    CHECK_THAT(refusal(bad), Catch::Contains("truncated"));
  }
  SECTION("empty file and trailing garbage") {
    write_bytes(bad, {});
    CHECK_THAT(refusal(bad), Catch::Contains("empty"));
    std::vector<char> longer = bytes;
    longer.push_back('x');
    write_bytes(bad, longer);
    CHECK_THAT(refusal(bad), Catch::Contains("unexpected bytes"));
  }
  SECTION("wrong kind") {
    std::vector<char> grid = bytes;
    std::copy_n("GRID", 4, grid.begin() + 8);
    write_bytes(bad, grid);
    CHECK_THAT(refusal(bad), Catch::Contains("is a grid file, expected a samples file"));
  }
  SECTION("newer format version") {
    std::vector<char> newer = bytes;
    newer[12] = static_cast<char>(kSamplesFormatVersion + 1);
    write_bytes(bad, newer);
    CHECK_THAT(refusal(bad), Catch::Contains("newer"));
  }
  SECTION("not an ncverify file") {
    write_bytes(bad, std::vector<char>(200, 'a'));
    CHECK_THAT(refusal(bad), Catch::Contains("not an ncverify file"));
  }
}
