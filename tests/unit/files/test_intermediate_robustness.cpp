// Regressions of the fuzz targets on the intermediate files: metadata that is well-formed
// JSON and carries a valid content hash, but holds the wrong kind of value where a count,
// offset or hash belongs. Each must be refused as bad input (InputError), never reach
// undefined behaviour or an unexpected exception.
#include <xxhash.h>
#include <catch2/catch.hpp>

#include <cstring>
#include <string>
#include <vector>

#include "files/container.hpp"
#include "files/grid_file.hpp"
#include "files/samples_file.hpp"
#include "util/error.hpp"

using namespace ncv;

namespace {

// A container of `kind` whose metadata is `meta_text` and whose sections are empty (at
// offset 1024, where the zero padding after the metadata ends): the header, the JSON, the
// padding and the XXH3 trailer, sized and hashed correctly.
ncv::Buffer<char> sealed_container(const char tag[4], std::uint32_t version,
                                   const std::string& meta_text) {
  REQUIRE(64 + meta_text.size() <= 1024);
  ncv::Buffer<char> bytes(1024 + 8, 0);
  const std::uint64_t meta_bytes = meta_text.size();
  const std::uint64_t file_bytes = bytes.size();
  std::memcpy(bytes.data(), "NCVERIFY", 8);
  std::memcpy(bytes.data() + 8, tag, 4);
  std::memcpy(bytes.data() + 12, &version, 4);
  std::memcpy(bytes.data() + 16, &meta_bytes, 8);
  std::memcpy(bytes.data() + 24, &file_bytes, 8);
  std::memcpy(bytes.data() + 64, meta_text.data(), meta_text.size());
  const std::uint64_t hash = XXH3_64bits(bytes.data(), 1024);
  std::memcpy(bytes.data() + 1024, &hash, 8);
  return bytes;
}

std::string section_table_refusal(const std::string& entry) {
  try {
    Container::parse(
        sealed_container("SMPL", kSamplesFormatVersion, R"({"sections": [)" + entry + "]}"),
        "x.samples", FileKind::samples, kSamplesFormatVersion);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

// Metadata with everything a loader reads before the mesh hash, which is `hash_json`: an
// empty mesh (its sections "<prefix>_vertices" and "<prefix>_triangles") described under
// `owner`.
std::string meta_with_hash(const std::string& owner, const std::string& prefix,
                           const std::string& hash_json) {
  const std::string empty = R"(", "offset": 1024, "bytes": 0, "shape": [0, 3]})";
  return R"({"sections": [{"name": ")" + prefix + R"(_vertices", "dtype": "<f8)" + empty +
         R"(, {"name": ")" + prefix + R"(_triangles", "dtype": "<u4)" + empty + R"(], ")" + owner +
         R"(": {"vertices": 0, "triangles": 0, "source": "a", "hash": )" + hash_json +
         R"(}, "sampling": {"samples": 0}})";
}

}  // namespace

TEST_CASE("section offsets, sizes and shapes must be JSON integers", "[intermediate-files]") {
  // A float beyond 2^64 used to be converted to an integer: undefined behaviour (found by
  // fuzz_distance_file); a fractional or negative one was silently truncated or wrapped.
  for (const std::string entry :
       {R"({"name": "p", "dtype": "<f8", "offset": 1.9e22, "bytes": 8, "shape": [1]})",
        R"({"name": "p", "dtype": "<f8", "offset": 64.5, "bytes": 8, "shape": [1]})",
        R"({"name": "p", "dtype": "<f8", "offset": 64, "bytes": -8, "shape": [1]})",
        R"({"name": "p", "dtype": "<f8", "offset": 64, "bytes": 8, "shape": [1.5]})",
        R"({"name": "p", "dtype": "<f8", "offset": 64, "bytes": 8, "shape": 1})",
        R"({"name": "p", "dtype": "<f8", "offset": "64", "bytes": 8, "shape": [1]})"}) {
    INFO(entry);
    CHECK_THAT(section_table_refusal(entry), Catch::Contains("malformed section table entry"));
  }
}

TEST_CASE("a mesh hash of the wrong JSON type is bad input", "[intermediate-files]") {
  // It used to escape as nlohmann::json::type_error instead of an InputError.
  for (const std::string hash : {"5", "null", "[1]"}) {
    INFO(hash);
    const ncv::Buffer<char> samples =
        sealed_container("SMPL", kSamplesFormatVersion, meta_with_hash("mesh", "mesh", hash));
    CHECK_THROWS_MATCHES(load_sample_set(Container::parse(samples, "x.samples", FileKind::samples,
                                                          kSamplesFormatVersion)),
                         InputError, Catch::Message("x.samples: mesh hash is malformed"));
    const ncv::Buffer<char> grid =
        sealed_container("GRID", kGridFormatVersion, meta_with_hash("nominal", "nominal", hash));
    CHECK_THROWS_MATCHES(load_indexed_reference(
                             Container::parse(grid, "x.grid", FileKind::grid, kGridFormatVersion)),
                         InputError, Catch::Message("x.grid: nominal hash is malformed"));
  }
}
