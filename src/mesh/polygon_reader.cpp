#include "mesh/polygon_reader.hpp"

#include <fmt/format.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <string_view>
#include <vector>

#include "util/error.hpp"

namespace ncv {
namespace {

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

std::string shown(std::string_view word) {
  std::string text;
  for (char c : word.substr(0, 24)) {
    text += static_cast<unsigned char>(c) >= 32 && static_cast<unsigned char>(c) < 127 ? c : '?';
  }
  return word.size() > 24 ? text + "..." : text;
}

// The text one line at a time, numbered from 1; '\n' ends a line, a '\r' before it is blank.
class Lines {
 public:
  explicit Lines(std::span<const char> bytes) : text_(bytes.data(), bytes.size()) {}

  bool next(std::string_view& line) {
    if (at_ >= text_.size()) return false;
    const std::size_t end = text_.find('\n', at_);
    const std::size_t stop = end == std::string_view::npos ? text_.size() : end;
    line = text_.substr(at_, stop - at_);
    at_ = end == std::string_view::npos ? text_.size() : end + 1;
    ++number_;
    return true;
  }
  std::size_t number() const { return number_; }
  std::size_t offset() const { return at_; }  // the first byte after the current line

 private:
  std::string_view text_;
  std::size_t at_ = 0;
  std::size_t number_ = 0;
};

// The blank-separated words of one line.
class Words {
 public:
  explicit Words(std::string_view line) : rest_(line) {}
  std::string_view next() {
    std::size_t start = 0;
    while (start < rest_.size() && is_blank(rest_[start])) ++start;
    std::size_t end = start;
    while (end < rest_.size() && !is_blank(rest_[end])) ++end;
    const std::string_view word = rest_.substr(start, end - start);
    rest_.remove_prefix(end);
    return word;
  }

 private:
  std::string_view rest_;
};

std::string_view without_comment(std::string_view line) {
  return line.substr(0, line.find('#'));
}

bool has_content(std::string_view line) {
  for (char c : line) {
    if (!is_blank(c)) return true;
  }
  return false;
}

// A number as written: parsed (with from_chars, so no locale and nothing left over; "nan"
// and "inf" parse), and whether it is a finite double.
struct Number {
  double value = 0;
  bool parsed = false;
  bool finite = false;
};

Number parse_number(std::string_view word) {
  if (word.starts_with('+')) word.remove_prefix(1);
  Number n;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), n.value);
  n.parsed = !word.empty() && end == word.data() + word.size() &&
             (error == std::errc() || error == std::errc::result_out_of_range);
  n.finite = n.parsed && error == std::errc() && std::isfinite(n.value);
  return n;
}

// A coordinate of OFF or OBJ, or the reason it is not one.
std::string coordinate_problem(std::string_view word, const Number& n) {
  if (!n.parsed) return fmt::format("coordinate '{}' is not a number", shown(word));
  if (!n.finite)
    return fmt::format("coordinate '{}' is NaN, infinite or out of range", shown(word));
  return {};
}

std::optional<std::int64_t> parse_integer(std::string_view word) {
  if (word.starts_with('+')) word.remove_prefix(1);
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (word.empty() || error != std::errc() || end != word.data() + word.size()) return {};
  return value;
}

// Collects vertices and fan-triangulated polygons, checking what every format must
// satisfy: polygons of three or more corners, indices within the vertex array.
class MeshBuilder {
 public:
  void add_vertex(Vec3 p) { mesh_.vertices.push_back(p); }
  std::size_t vertex_count() const { return mesh_.vertices.size(); }

  // Empty when fine, else the problem.
  std::string add_polygon(const std::vector<std::int64_t>& corners) {
    if (corners.size() < 3) return fmt::format("a face has {} corners", corners.size());
    for (std::int64_t v : corners) {
      if (v < 0 || v > std::numeric_limits<std::uint32_t>::max()) {
        return fmt::format("a face refers to vertex {}", v);
      }
    }
    for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
      mesh_.triangles.push_back({static_cast<std::uint32_t>(corners[0]),
                                 static_cast<std::uint32_t>(corners[k]),
                                 static_cast<std::uint32_t>(corners[k + 1])});
    }
    return {};
  }

  // Faces may precede vertices in a PLY, so indices are checked once all are read.
  Mesh finish(const std::string& source, std::string_view format) {
    for (const Triangle& t : mesh_.triangles) {
      for (std::uint32_t v : t) {
        if (v >= mesh_.vertices.size()) {
          throw InputError(source, fmt::format("{}: a face refers to vertex {}, but there are {} "
                                               "vertices",
                                               format, v, mesh_.vertices.size()));
        }
      }
    }
    return std::move(mesh_);
  }

 private:
  Mesh mesh_;
};

// ------------------------------------------------------------------------------------ PLY

struct PlyType {
  int bytes = 0;
  bool is_float = false;
  bool is_signed = false;
};

std::optional<PlyType> ply_type(std::string_view name) {
  if (name == "char" || name == "int8") return PlyType{1, false, true};
  if (name == "uchar" || name == "uint8") return PlyType{1, false, false};
  if (name == "short" || name == "int16") return PlyType{2, false, true};
  if (name == "ushort" || name == "uint16") return PlyType{2, false, false};
  if (name == "int" || name == "int32") return PlyType{4, false, true};
  if (name == "uint" || name == "uint32") return PlyType{4, false, false};
  if (name == "float" || name == "float32") return PlyType{4, true, true};
  if (name == "double" || name == "float64") return PlyType{8, true, true};
  return {};
}

struct PlyProperty {
  std::string name;
  PlyType type;
  bool is_list = false;
  PlyType count_type;
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

enum class PlyEncoding { ascii, little_endian, big_endian };

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::ascii;
  std::vector<PlyElement> elements;
  std::size_t body_offset = 0;
  std::size_t body_line = 0;  // the number of the header's last line
};

class PlyHeaderParser {
 public:
  PlyHeaderParser(std::span<const char> bytes, const std::string& source)
      : lines_(bytes), source_(source) {}

  PlyHeader parse() {
    std::string_view line;
    if (!lines_.next(line) || Words(line).next() != "ply")
      fail("the file does not start with 'ply'");
    bool has_format = false;
    for (;;) {
      if (!lines_.next(line)) fail("the header has no end_header line (truncated?)");
      Words words(line);
      const std::string_view keyword = words.next();
      if (keyword == "end_header") break;
      if (keyword == "comment" || keyword == "obj_info" || keyword.empty()) continue;
      if (keyword == "format") {
        header_.encoding = encoding(words.next());
        has_format = true;
      } else if (keyword == "element") {
        element(words);
      } else if (keyword == "property") {
        property(words);
      } else {
        fail(fmt::format("unexpected header line starting with '{}'", shown(keyword)));
      }
    }
    if (!has_format) fail("the header has no format line");
    header_.body_offset = lines_.offset();
    header_.body_line = lines_.number();
    return header_;
  }

 private:
  PlyEncoding encoding(std::string_view name) {
    if (name == "ascii") return PlyEncoding::ascii;
    if (name == "binary_little_endian") return PlyEncoding::little_endian;
    if (name == "binary_big_endian") return PlyEncoding::big_endian;
    fail(fmt::format("unknown format '{}'", shown(name)));
  }

  void element(Words& words) {
    PlyElement e;
    e.name = words.next();
    const std::optional<std::int64_t> count = parse_integer(words.next());
    if (e.name.empty() || !count || *count < 0) fail("an element line needs a name and a count");
    e.count = static_cast<std::uint64_t>(*count);
    header_.elements.push_back(std::move(e));
  }

  void property(Words& words) {
    if (header_.elements.empty()) fail("a property precedes every element");
    PlyProperty p;
    std::string_view type = words.next();
    if (type == "list") {
      p.is_list = true;
      p.count_type = checked_type(words.next());
      if (p.count_type.is_float) fail("a list count must have an integer type");
      type = words.next();
    }
    p.type = checked_type(type);
    p.name = words.next();
    if (p.name.empty()) fail("a property has no name");
    header_.elements.back().properties.push_back(std::move(p));
  }

  PlyType checked_type(std::string_view name) {
    const std::optional<PlyType> type = ply_type(name);
    if (!type) fail(fmt::format("unknown property type '{}'", shown(name)));
    return *type;
  }

  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(source_, fmt::format("PLY, line {}: {}", lines_.number(), problem));
  }

  Lines lines_;
  const std::string& source_;
  PlyHeader header_;
};

// The values of an ASCII body, word by word across lines.
class PlyAsciiValues {
 public:
  PlyAsciiValues(std::string_view body, std::size_t line, const std::string& source)
      : body_(body), line_(line), source_(source) {}

  bool at_end() {
    skip_blanks();
    return at_ >= body_.size();
  }
  // NaN and out-of-range values are kept (scanners write NaN normals, which are ignored);
  // coordinates are checked for being finite where they are used.
  double number(const PlyType&) {
    const std::string_view w = word();
    const Number n = parse_number(w);
    if (!n.parsed) fail(fmt::format("'{}' is not a number", shown(w)));
    return n.finite ? n.value : std::numeric_limits<double>::quiet_NaN();
  }
  std::int64_t integer(const PlyType&) {
    const std::string_view w = word();
    const std::optional<std::int64_t> value = parse_integer(w);
    if (!value) fail(fmt::format("'{}' is not an integer", shown(w)));
    return *value;
  }
  // The values a list of `count` items needs at least (one byte each, blank or not).
  bool can_hold(std::int64_t count, const PlyType&) const {
    return static_cast<std::uint64_t>(count) <= body_.size() - at_;
  }
  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(source_, fmt::format("PLY, line {}: {}", line_, problem));
  }

 private:
  void skip_blanks() {
    while (at_ < body_.size() && is_blank(body_[at_])) {
      if (body_[at_] == '\n') ++line_;
      ++at_;
    }
  }
  std::string_view word() {
    skip_blanks();
    if (at_ >= body_.size()) fail("the data ends early (truncated?)");
    const std::size_t start = at_;
    while (at_ < body_.size() && !is_blank(body_[at_])) ++at_;
    return body_.substr(start, at_ - start);
  }

  std::string_view body_;
  std::size_t at_ = 0;
  std::size_t line_;
  const std::string& source_;
};

// The values of a binary body, checked against its end before every read.
class PlyBinaryValues {
 public:
  PlyBinaryValues(std::span<const char> bytes, std::size_t offset, bool big_endian,
                  const std::string& source)
      : bytes_(bytes),
        at_(offset),
        swap_(big_endian != (std::endian::native == std::endian::big)),
        source_(source) {}

  bool at_end() const { return at_ >= bytes_.size(); }
  double number(const PlyType& type) {
    const std::uint64_t bits = take(type.bytes);
    if (type.is_float) {
      if (type.bytes == 4)
        return static_cast<double>(std::bit_cast<float>(static_cast<std::uint32_t>(bits)));
      return std::bit_cast<double>(bits);
    }
    return static_cast<double>(as_integer(bits, type));
  }
  std::int64_t integer(const PlyType& type) { return as_integer(take(type.bytes), type); }
  bool can_hold(std::int64_t count, const PlyType& type) const {
    return static_cast<std::uint64_t>(count) <=
           (bytes_.size() - at_) / static_cast<std::size_t>(type.bytes);
  }
  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(source_, fmt::format("PLY, at byte {}: {}", at_, problem));
  }

 private:
  std::uint64_t take(int width) {
    const auto n = static_cast<std::size_t>(width);
    if (bytes_.size() - at_ < n) fail("the data ends early (truncated?)");
    unsigned char raw[8] = {};
    std::memcpy(raw, bytes_.data() + at_, n);
    at_ += n;
    std::uint64_t bits = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t from = swap_ ? n - 1 - k : k;
      bits |= std::uint64_t{raw[from]} << (8 * k);
    }
    return bits;
  }
  static std::int64_t as_integer(std::uint64_t bits, const PlyType& type) {
    if (!type.is_signed || type.bytes == 8) return static_cast<std::int64_t>(bits);
    const int shift = 64 - 8 * type.bytes;  // sign-extend
    return static_cast<std::int64_t>(bits << shift) >> shift;
  }

  std::span<const char> bytes_;
  std::size_t at_;
  bool swap_;
  const std::string& source_;
};

template <class Values>
Mesh read_ply_body(const PlyHeader& header, Values& values, const std::string& source) {
  MeshBuilder builder;
  bool has_vertices = false;
  std::vector<std::int64_t> corners;
  for (const PlyElement& element : header.elements) {
    const bool is_vertex = element.name == "vertex";
    const bool is_face = element.name == "face";
    int axis_of[3] = {-1, -1, -1};  // property index of x, y, z
    int indices = -1;               // property index of the corner list
    for (std::size_t p = 0; p < element.properties.size(); ++p) {
      const PlyProperty& property = element.properties[p];
      for (int axis = 0; axis < 3; ++axis) {
        if (is_vertex && !property.is_list && property.name == std::string(1, "xyz"[axis])) {
          axis_of[axis] = static_cast<int>(p);
        }
      }
      if (is_face && property.is_list &&
          (property.name == "vertex_indices" || property.name == "vertex_index")) {
        if (property.type.is_float) values.fail("face vertex indices must have an integer type");
        indices = static_cast<int>(p);
      }
    }
    if (is_vertex) {
      if (axis_of[0] < 0 || axis_of[1] < 0 || axis_of[2] < 0) {
        values.fail("element 'vertex' lacks one of the properties x, y, z");
      }
      has_vertices = true;
    }
    if (is_face && indices < 0) values.fail("element 'face' has no vertex_indices list");
    // Each item takes at least one value, so this loop ends with the data whatever the
    // count claims; an element without properties would take none.
    if (element.properties.empty() && element.count > 0) {
      values.fail(fmt::format("element '{}' has no properties", shown(element.name)));
    }
    for (std::uint64_t item = 0; item < element.count; ++item) {
      if (values.at_end()) {
        values.fail(fmt::format("element '{}' claims {} items, the data ends after {}",
                                shown(element.name), element.count, item));
      }
      Vec3 point{0, 0, 0};
      for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const PlyProperty& property = element.properties[p];
        if (!property.is_list) {
          const double value = values.number(property.type);
          for (int axis = 0; axis < 3; ++axis) {
            if (axis_of[axis] == static_cast<int>(p)) point[axis] = value;
          }
          continue;
        }
        const std::int64_t count = values.integer(property.count_type);
        if (count < 0 || !values.can_hold(count, property.type)) {
          values.fail(fmt::format("a list claims {} values, more than the data holds", count));
        }
        const bool keep = static_cast<int>(p) == indices;
        if (keep) corners.clear();
        for (std::int64_t k = 0; k < count; ++k) {
          if (keep) {
            corners.push_back(values.integer(property.type));
          } else {
            values.number(property.type);
          }
        }
      }
      if (is_vertex) {
        if (!is_finite(point)) {
          values.fail(
              fmt::format("vertex {} has a NaN, infinite or out-of-range coordinate", item));
        }
        builder.add_vertex(point);
      }
      if (is_face) {
        if (const std::string problem = builder.add_polygon(corners); !problem.empty()) {
          values.fail(fmt::format("face {}: {}", item, problem));
        }
      }
    }
  }
  if (!has_vertices) values.fail("no element 'vertex'");
  if (!values.at_end()) values.fail("unexpected data after the last element");
  return builder.finish(source, "PLY");
}

// ------------------------------------------------------------------------------------ OFF

class OffParser {
 public:
  OffParser(std::span<const char> bytes, const std::string& source)
      : lines_(bytes), source_(source) {}

  Mesh parse() {
    Words header(next_content_line("the file is empty"));
    keyword(header.next());
    std::vector<std::int64_t> counts;
    for (std::string_view w = header.next(); !w.empty(); w = header.next()) {
      if (w == "BINARY") fail("binary OFF is not supported; convert it to ASCII OFF, PLY or STL");
      counts.push_back(count(w));
    }
    if (counts.empty()) {
      Words line(next_content_line("the file ends before the vertex and face counts"));
      for (std::string_view w = line.next(); !w.empty(); w = line.next())
        counts.push_back(count(w));
    }
    if (counts.size() < 2 || counts.size() > 3) {
      fail("expected the vertex, face and edge counts");
    }
    for (std::int64_t v = 0; v < counts[0]; ++v) vertex();
    std::vector<std::int64_t> corners;
    for (std::int64_t f = 0; f < counts[1]; ++f) face(f, corners);
    std::string_view line;
    while (lines_.next(line)) {
      if (has_content(without_comment(line))) fail("unexpected data after the last face");
    }
    return builder_.finish(source_, "OFF");
  }

 private:
  // [ST][C][N]OFF; the prefixes announce extra per-vertex values, which are ignored.
  void keyword(std::string_view word) {
    std::string_view rest = word;
    for (std::string_view prefix : {"ST", "C", "N"}) {
      if (rest.starts_with(prefix)) rest.remove_prefix(prefix.size());
    }
    if (rest.starts_with("4") || rest.starts_with("n")) {
      fail("OFF with other than three coordinates per vertex is not supported");
    }
    if (rest != "OFF") fail(fmt::format("expected the OFF keyword, found '{}'", shown(word)));
  }

  std::int64_t count(std::string_view word) {
    const std::optional<std::int64_t> value = parse_integer(word);
    if (!value || *value < 0) fail(fmt::format("'{}' is not a count", shown(word)));
    return *value;
  }

  void vertex() {
    Words words(next_content_line("the file ends before the last vertex (truncated?)"));
    Vec3 p{0, 0, 0};
    for (int axis = 0; axis < 3; ++axis) {
      const std::string_view w = words.next();
      if (w.empty()) fail("a vertex has fewer than three coordinates");
      const Number n = parse_number(w);
      if (const std::string problem = coordinate_problem(w, n); !problem.empty()) fail(problem);
      p[axis] = n.value;
    }
    builder_.add_vertex(p);
  }

  // "n i1 ... in" and possibly a colour, which is ignored.
  void face(std::int64_t f, std::vector<std::int64_t>& corners) {
    Words words(next_content_line("the file ends before the last face (truncated?)"));
    const std::int64_t n = count(words.next());
    corners.clear();
    for (std::int64_t k = 0; k < n; ++k) {
      const std::string_view w = words.next();
      if (w.empty()) fail(fmt::format("face {} lists fewer than its {} corners", f, n));
      const std::optional<std::int64_t> index = parse_integer(w);
      if (!index) fail(fmt::format("'{}' is not a vertex index", shown(w)));
      corners.push_back(*index);
    }
    if (const std::string problem = builder_.add_polygon(corners); !problem.empty()) {
      fail(fmt::format("face {}: {}", f, problem));
    }
  }

  std::string_view next_content_line(const char* at_end) {
    std::string_view line;
    while (lines_.next(line)) {
      line = without_comment(line);
      if (has_content(line)) return line;
    }
    fail(at_end);
  }

  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(source_, fmt::format("OFF, line {}: {}", lines_.number(), problem));
  }

  Lines lines_;
  const std::string& source_;
  MeshBuilder builder_;
};

// ------------------------------------------------------------------------------------ OBJ

class ObjParser {
 public:
  ObjParser(std::span<const char> bytes, const std::string& source)
      : lines_(bytes), source_(source) {}

  Mesh parse() {
    std::string_view line;
    std::vector<std::int64_t> corners;
    while (lines_.next(line)) {
      line = without_comment(line);
      const std::size_t last = line.find_last_not_of(" \t\r");
      if (last != std::string_view::npos && line[last] == '\\') {
        fail("line continuations are not supported");
      }
      Words words(line);
      const std::string_view statement = words.next();
      if (statement == "v") vertex(words);
      if (statement == "f") face(words, corners);
    }
    return builder_.finish(source_, "OBJ");
  }

 private:
  void vertex(Words& words) {
    Vec3 p{0, 0, 0};
    for (int axis = 0; axis < 3; ++axis) {
      const std::string_view w = words.next();
      if (w.empty()) fail("a vertex has fewer than three coordinates");
      const Number n = parse_number(w);
      if (const std::string problem = coordinate_problem(w, n); !problem.empty()) fail(problem);
      p[axis] = n.value;
    }
    builder_.add_vertex(p);
  }

  // Corners "i", "i/t", "i//n" or "i/t/n"; i counts from 1, or back from the last vertex
  // read so far when negative.
  void face(Words& words, std::vector<std::int64_t>& corners) {
    corners.clear();
    for (std::string_view w = words.next(); !w.empty(); w = words.next()) {
      const std::string_view index_text = w.substr(0, w.find('/'));
      const std::optional<std::int64_t> index = parse_integer(index_text);
      if (!index || *index == 0) fail(fmt::format("'{}' is not a vertex index", shown(w)));
      const auto defined = static_cast<std::int64_t>(builder_.vertex_count());
      if (*index < -defined) {
        fail(fmt::format("vertex {} counts back past the first vertex", *index));
      }
      corners.push_back(*index > 0 ? *index - 1 : defined + *index);
    }
    if (const std::string problem = builder_.add_polygon(corners); !problem.empty()) fail(problem);
  }

  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(source_, fmt::format("OBJ, line {}: {}", lines_.number(), problem));
  }

  Lines lines_;
  const std::string& source_;
  MeshBuilder builder_;
};

}  // namespace

Mesh parse_ply(std::span<const char> bytes, const std::string& source) {
  const PlyHeader header = PlyHeaderParser(bytes, source).parse();
  if (header.encoding == PlyEncoding::ascii) {
    PlyAsciiValues values(std::string_view(bytes.data(), bytes.size()).substr(header.body_offset),
                          header.body_line + 1, source);
    return read_ply_body(header, values, source);
  }
  PlyBinaryValues values(bytes, header.body_offset, header.encoding == PlyEncoding::big_endian,
                         source);
  return read_ply_body(header, values, source);
}

Mesh parse_off(std::span<const char> bytes, const std::string& source) {
  return OffParser(bytes, source).parse();
}

Mesh parse_obj(std::span<const char> bytes, const std::string& source) {
  return ObjParser(bytes, source).parse();
}

}  // namespace ncv
