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

  // Many blocks (checked and converted in parallel): one double in the last block decides.
  std::vector<Vec3> many(200000);
  for (std::size_t i = 0; i < many.size(); ++i) {
    const auto x = static_cast<float>(i) * 0.25f;
    many[i] = Vec3(x, -x, 1.0f / static_cast<float>(i + 1));
  }
  const Container m = round_trip(dir, [&](ContainerWriter& w) { w.add_points("p", many); });
  CHECK(m.dtype("p") == "<f4");
  CHECK(m.get_points("p", many.size()) == many);
  many.back()[1] = 0.1;
  const Container n = round_trip(dir, [&](ContainerWriter& w) { w.add_points("p", many); });
  CHECK(n.dtype("p") == "<f8");
  CHECK(n.get_points("p", many.size()) == many);
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
  // Many blocks (made in parallel): the largest in the last decides the type.
  std::vector<std::uint32_t> many(300000);
  for (std::size_t i = 0; i < many.size(); ++i) many[i] = static_cast<std::uint32_t>(i % 251);
  for (const auto& [last, dtype] :
       {std::pair<std::uint32_t, const char*>{250, "<u1"}, {70000, "<u4"}}) {
    many.back() = last;
    const Container big = round_trip(dir, [&](ContainerWriter& w) { w.add_counts("n", many); });
    CHECK(big.dtype("n") == dtype);
    CHECK(big.get_counts("n", many.size()) == many);
  }
  const Container c = round_trip(dir, [](ContainerWriter& w) {
    w.add_counts("n", std::vector<std::uint32_t>{1, 2});  // a temporary: add_counts keeps it
  });
  CHECK_THROWS_AS(c.get_counts("n", 3), InputError);
  CHECK_THROWS_AS(c.get_counts("missing", 2), InputError);
}
