// The two STL parsers called directly on any bytes, whatever the detection in parse_mesh
// would have chosen: the binary reader must refuse every size that does not match its
// header's count before allocating, the ASCII reader every malformed or truncated text.
#include "fuzz_support.hpp"
#include "mesh/stl_reader.hpp"

namespace {

void check_promise(const ncv::Mesh& mesh) {
  for (const ncv::Triangle& t : mesh.triangles) {
    for (std::uint32_t v : t) {
      if (v >= mesh.vertex_count()) __builtin_trap();
    }
  }
  for (const ncv::Vec3& p : mesh.vertices) {
    if (!ncv::is_finite(p)) __builtin_trap();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ncv::fuzz::quiet_and_serial();
  const std::span<const char> bytes(reinterpret_cast<const char*>(data), size);
  ncv::fuzz::accepts([&] { check_promise(ncv::parse_binary_stl(bytes, "fuzz.stl")); });
  ncv::fuzz::accepts([&] { check_promise(ncv::parse_ascii_stl(bytes, "fuzz.stl")); });
  return 0;
}
