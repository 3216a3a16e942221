#include "mesh/stl_reader.hpp"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <string_view>

#include "mesh/facet_weld.hpp"
#include "mesh/vertex_welder.hpp"
#include "util/error.hpp"

namespace ncv {
namespace {

constexpr std::size_t kBinaryHeader = 84;
constexpr std::size_t kBinaryFacet = 50;

std::uint32_t binary_triangle_count(std::span<const char> bytes) {
  std::uint32_t count;
  std::memcpy(&count, bytes.data() + 80, sizeof count);
  return count;
}

InputError non_finite_coordinate(std::uint64_t triangle, const std::string& source) {
  return InputError(source, fmt::format("triangle {} has a NaN or infinite coordinate", triangle));
}

void check_finite(Vec3 p, std::uint64_t triangle, const std::string& source) {
  if (!is_finite(p)) throw non_finite_coordinate(triangle, source);
}

// Splits ASCII STL into whitespace-separated words, tracking the line for messages.
class Words {
 public:
  explicit Words(std::span<const char> text) : text_(text.data(), text.size()) {}

  std::string_view next() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) {
      if (text_[at_] == '\n') ++line_;
      ++at_;
    }
    const std::size_t start = at_;
    while (at_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
    return text_.substr(start, at_ - start);
  }
  void skip_line() {
    while (at_ < text_.size() && text_[at_] != '\n') ++at_;
  }
  std::size_t line() const { return line_; }

 private:
  std::string_view text_;
  std::size_t at_ = 0;
  std::size_t line_ = 1;
};

class AsciiStlParser {
 public:
  AsciiStlParser(std::span<const char> bytes, const std::string& source)
      : words_(bytes), source_(source), welder_(bytes.size() / 200) {}

  Mesh parse() {
    expect("solid");
    words_.skip_line();  // the solid's name
    // A missing 'endsolid' is the only trace of a file cut between two facets, so it is
    // required: a truncated part must not verify as a smaller one.
    for (;;) {
      const std::string_view word = words_.next();
      if (word.empty()) fail("truncated: the file ends before 'endsolid'");
      if (word == "facet") {
        parse_facet();
        continue;
      }
      if (word != "endsolid") {
        fail(fmt::format("expected 'facet' or 'endsolid', found '{}'", printable(word)));
      }
      words_.skip_line();
      const std::string_view after = words_.next();
      if (after.empty()) break;
      if (after != "solid") fail(fmt::format("expected 'solid' or the end, found '{}'", after));
      words_.skip_line();
    }
    Mesh mesh;
    mesh.vertices = welder_.take_vertices();
    mesh.triangles = std::move(triangles_);
    return mesh;
  }

 private:
  void parse_facet() {
    expect("normal");
    for (int k = 0; k < 3; ++k) number();  // the stored normal is not trusted
    expect("outer");
    expect("loop");
    Triangle triangle;
    for (int k = 0; k < 3; ++k) {
      expect("vertex");
      const Vec3 p{number(), number(), number()};
      check_finite(p, triangles_.size(), source_);
      triangle[k] = welder_.weld(p);
    }
    expect("endloop");
    expect("endfacet");
    triangles_.push_back(triangle);
  }

  double number() {
    const std::string_view word = words_.next();
    double value = 0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (word.empty()) fail("truncated: the file ends inside a facet");
    // from_chars reports out-of-range values and does not accept "nan"/"inf" spellings
    // that STL writers produce; both are non-finite coordinates here.
    if (error == std::errc::result_out_of_range || word == "nan" || word == "-nan" ||
        word == "inf" || word == "-inf" || word == "NaN" || word == "Inf") {
      throw InputError(
          source_, fmt::format("triangle {} has a NaN or infinite coordinate", triangles_.size()));
    }
    if (error != std::errc() || end != word.data() + word.size()) {
      fail(fmt::format("expected a number, found '{}'", printable(word)));
    }
    return value;
  }

  void expect(std::string_view keyword) {
    const std::string_view word = words_.next();
    if (word.empty())
      fail(fmt::format("truncated: the file ends where '{}' was expected", keyword));
    if (word != keyword) {
      fail(fmt::format("expected '{}', found '{}'", keyword, printable(word)));
    }
  }

  static std::string printable(std::string_view word) {
    std::string shown;
    for (char c : word.substr(0, 24)) {
      shown += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
    }
    return word.size() > 24 ? shown + "..." : shown;
  }

  [[noreturn]] void fail(const std::string& problem) {
    throw InputError(source_, fmt::format("ASCII STL, line {}: {}", words_.line(), problem));
  }

  Words words_;
  const std::string& source_;
  VertexWelder welder_;
  std::vector<Triangle> triangles_;
};

}  // namespace

bool looks_like_binary_stl(std::span<const char> bytes) {
  return bytes.size() >= kBinaryHeader &&
         bytes.size() == kBinaryHeader + kBinaryFacet * std::uint64_t{binary_triangle_count(bytes)};
}

bool looks_like_ascii_stl(std::span<const char> bytes) {
  std::size_t at = 0;
  while (at < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[at]))) ++at;
  return bytes.size() - at >= 5 && std::memcmp(bytes.data() + at, "solid", 5) == 0;
}

Mesh parse_binary_stl(std::span<const char> bytes, const std::string& source) {
  if (bytes.size() < kBinaryHeader) {
    throw InputError(source, fmt::format("truncated binary STL: {} bytes, shorter than the "
                                         "84-byte header",
                                         bytes.size()));
  }
  const std::uint64_t count = binary_triangle_count(bytes);
  const std::uint64_t expected = kBinaryHeader + kBinaryFacet * count;
  // Checked before any allocation, so no header can make us reserve memory it does not back.
  if (expected != bytes.size()) {
    throw InputError(source, fmt::format("not a valid binary STL: its header claims {} triangles "
                                         "({} bytes) but the file has {} bytes",
                                         count, expected, bytes.size()));
  }
  if (count == 0) throw InputError(source, "binary STL with no triangles");
  // Corner indices are 32-bit in the weld (and vertex indices everywhere).
  if (3 * count > std::numeric_limits<std::uint32_t>::max()) {
    throw InputError(source, fmt::format("{} triangles are too many (at most {})", count,
                                         std::numeric_limits<std::uint32_t>::max() / 3));
  }
  WeldedFacets welded = weld_binary_facets(bytes.data() + kBinaryHeader, count);
  if (welded.non_finite) throw non_finite_coordinate(*welded.non_finite, source);
  return std::move(welded.mesh);
}

Mesh parse_ascii_stl(std::span<const char> bytes, const std::string& source) {
  Mesh mesh = AsciiStlParser(bytes, source).parse();
  if (mesh.triangles.empty()) throw InputError(source, "ASCII STL with no triangles");
  return mesh;
}

}  // namespace ncv
