// Sections the container narrows without changing a value: points stored as floats when
// every coordinate is one exactly, counts in the narrowest unsigned type that holds them.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include "files/container.hpp"
#include "scratch_dir.hpp"

using namespace ncv;

namespace {

// Writes one section with `add` and reads the file back.
template <class Add>
Container round_trip(const ScratchDir& dir, Add&& add) {
  ContainerWriter writer(FileKind::samples, kSamplesFormatVersion, nlohmann::json::object());
  add(writer);
  const std::string path = (dir.path() / "sections.samples").string();
  OutputFile out(path, OutputKind::binary);
  writer.write(out);
  out.commit();
  return Container::read(path, FileKind::samples, kSamplesFormatVersion);
}

}  // namespace

TEST_CASE("points that are floats are stored as floats, others as doubles, exactly",
          "[container]") {
  const ScratchDir dir;
  const std::vector<Vec3> floats = {Vec3(0, -0.0, 1.5), Vec3(0.1f, 1e30f, -3.25f),
                                    Vec3(std::numeric_limits<float>::denorm_min(), 7, 1e-30f)};
  const Container a = round_trip(dir, [&](ContainerWriter& w) { w.add_points("p", floats); });
  CHECK(a.dtype("p") == "<f4");
  const std::vector<Vec3> back = a.get_points("p", floats.size());
  for (std::size_t i = 0; i < floats.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      CHECK(back[i][k] == floats[i][k]);
      CHECK(std::signbit(back[i][k]) == std::signbit(floats[i][k]));
    }
  }

  std::vector<Vec3> doubles = floats;
  doubles[1][2] = 0.1;  // not a float: every point is stored as double
  const Container b = round_trip(dir, [&](ContainerWriter& w) { w.add_points("p", doubles); });
  CHECK(b.dtype("p") == "<f8");
  CHECK(b.get_points("p", doubles.size()) == doubles);
  CHECK_THROWS_AS(b.get_points("p", doubles.size() + 1), InputError);
}

TEST_CASE("counts are stored in the narrowest unsigned type that holds the largest",
          "[container]") {
  const ScratchDir dir;
  const std::vector<std::pair<std::vector<std::uint32_t>, const char*>> cases = {
      {{0, 1, 255}, "<u1"}, {{0, 256, 3}, "<u2"},      {{65535}, "<u2"},
      {{65536, 0}, "<u4"},  {{4294967295u, 7}, "<u4"}, {{}, "<u1"}};
  for (const auto& [counts, dtype] : cases) {
    const Container c = round_trip(dir, [&](ContainerWriter& w) { w.add_counts("n", counts); });
    CHECK(c.dtype("n") == dtype);
    CHECK(c.get_counts("n", counts.size()) == counts);
  }
  const Container c = round_trip(dir, [](ContainerWriter& w) { w.add_counts("n", {1, 2}); });
  CHECK_THROWS_AS(c.get_counts("n", 3), InputError);
  CHECK_THROWS_AS(c.get_counts("missing", 2), InputError);
}
