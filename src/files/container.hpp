// The ncverify container: the one binary layout shared by the samples, grid and distance
// files (docs/FORMATS.md documents it byte by byte).
//
//   offset 0   char[8]  magic "NCVERIFY"
//          8   char[4]  kind: "SMPL", "GRID" or "DIST"
//          12  u32      format version
//          16  u64      meta_bytes: length of the JSON metadata that starts at offset 64
//          24  u64      file_bytes: length of the whole file, trailer included
//          32  u8[32]   zero
//          64  JSON metadata (parameters, counts, hashes and the section table), then
//              sections, each at a 64-byte aligned offset, zero padding between
//          file_bytes-8  u64  XXH3-64 of every byte before it
//
// All integers and arrays are little-endian. Each section is a C-order array whose dtype
// ("<f8", "<u4", "<u8") and shape the section table gives, so numpy reads it with
// np.frombuffer(buffer, dtype, count, offset).
#pragma once

#include <cstdint>
#include <cstring>
#include <deque>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "geometry/vec3.hpp"
#include "util/buffer.hpp"
#include "util/error.hpp"
#include "util/input_bytes.hpp"
#include "util/output_file.hpp"

namespace ncv {

enum class FileKind { samples, grid, distances };

// The format version this build writes and reads, per kind.
inline constexpr std::uint32_t kSamplesFormatVersion = 3;
inline constexpr std::uint32_t kGridFormatVersion = 3;
inline constexpr std::uint32_t kDistancesFormatVersion = 3;
std::uint32_t format_version(FileKind kind);

std::string kind_tag(FileKind kind);          // "SMPL", ...
std::string kind_description(FileKind kind);  // "samples file", ...

template <class T>
constexpr const char* dtype_of();
template <>
constexpr const char* dtype_of<double>() {
  return "<f8";
}
template <>
constexpr const char* dtype_of<float>() {
  return "<f4";
}
template <>
constexpr const char* dtype_of<std::uint8_t>() {
  return "<u1";
}
template <>
constexpr const char* dtype_of<std::uint16_t>() {
  return "<u2";
}
template <>
constexpr const char* dtype_of<std::uint32_t>() {
  return "<u4";
}
template <>
constexpr const char* dtype_of<std::uint64_t>() {
  return "<u8";
}

class ContainerWriter {
 public:
  ContainerWriter(FileKind kind, std::uint32_t version, nlohmann::json meta);

  // The data must stay alive until write(); shape's product times the width of T must
  // equal the span's size in bytes.
  template <class T>
  void add(std::string name, std::span<const T> data, std::vector<std::uint64_t> shape) {
    add_raw(std::move(name), dtype_of<T>(), sizeof(T), data.data(), data.size_bytes(),
            std::move(shape));
  }
  // Counts in the narrowest unsigned type that holds the largest (<u1, <u2 or <u4): most
  // are small, so a byte each. Read back with Container::get_counts. Kept: `counts` need not
  // outlive the call.
  void add_counts(std::string name, std::span<const std::uint32_t> counts);
  // Points as <f4 when every coordinate is a float exactly (as binary STL gives them), else
  // <f8: half the bytes, the same values. Read back with Container::get_points.
  void add_points(std::string name, std::span<const Vec3> points);
  // Returns the content hash (the trailer) of what it wrote.
  std::uint64_t write(OutputFile& out);

 private:
  struct Section {
    std::string name, dtype;
    std::size_t width;
    const void* data;
    std::uint64_t bytes;
    std::vector<std::uint64_t> shape;
  };
  void add_raw(std::string name, const char* dtype, std::size_t width, const void* data,
               std::uint64_t bytes, std::vector<std::uint64_t> shape);

  FileKind kind_;
  std::uint32_t version_;
  nlohmann::json meta_;
  std::vector<Section> sections_;
  // Room for `count` values of a section made on the fly, kept until write(); unwritten, for
  // a parallel loop to fill (the grid file's cell counts, serial, were a tenth of its write).
  template <class T>
  std::span<T> kept_array(std::size_t count) {
    Buffer<char>& bytes = kept_.emplace_back(count * sizeof(T));
    return {reinterpret_cast<T*>(bytes.data()), count};
  }

  std::deque<Buffer<char>> kept_;  // a deque: a kept buffer never moves
};

// A parsed, verified container: magic, kind, version, sizes and content hash all checked.
class Container {
 public:
  static Container parse(InputBytes bytes, const std::string& source, FileKind kind,
                         std::uint32_t version);
  static Container read(const std::string& path, FileKind kind, std::uint32_t version);
  // Reads any kind, in its current version (for inspect).
  static Container read_any(const std::string& path);

  FileKind kind() const { return kind_; }
  std::uint32_t version() const { return version_; }
  const nlohmann::json& meta() const { return meta_; }
  const std::string& source() const { return source_; }
  std::uint64_t file_bytes() const { return bytes_.size(); }
  // The XXH3-64 of the file's content (its trailer): what a distance file names its samples
  // file by.
  std::uint64_t content_hash() const;
  // The dtype of section `name` (the section must exist).
  const std::string& dtype(const std::string& name) const { return section(name).dtype; }

  bool has(const std::string& name) const;
  // Copies section `name`, checking its dtype and that it holds `rows` values, into a
  // std::vector<T> or a Buffer<T>.
  template <class T, class Vector = std::vector<T>>
  Vector get(const std::string& name, std::uint64_t rows) const {
    return get_rows<T, T, Vector>(name, rows);
  }
  // The same for a section of rows × sizeof(Row) / sizeof(T) elements, copied straight into
  // `rows` Rows (points as Vec3, triangles as Triangle): one copy, no flat array between.
  template <class T, class Row, class Vector = std::vector<Row>>
  Vector get_rows(const std::string& name, std::uint64_t rows) const {
    static_assert(std::is_trivially_copyable_v<Row> && sizeof(Row) % sizeof(T) == 0);
    constexpr std::uint64_t columns = sizeof(Row) / sizeof(T);
    Vector out(checked_count(name, dtype_of<T>(), rows, columns) / columns);
    copy_section(name, out.data(), out.size() * sizeof(Row));
    return out;
  }
  // A section written by ContainerWriter::add_counts, `rows` values, widened.
  std::vector<std::uint32_t> get_counts(const std::string& name, std::uint64_t rows) const;
  // A section written by ContainerWriter::add_points, `rows` points, widened exactly.
  std::vector<Vec3> get_points(const std::string& name, std::uint64_t rows) const;
  // Raw access for generic tools (inspect): the bytes are little-endian `dtype` values.
  struct RawSection {
    std::string dtype;
    std::uint64_t elements;
    std::uint64_t columns;  // the product of the shape after its first dimension
    const char* data;
  };
  RawSection raw_section(const std::string& name) const;
  // A required metadata field, with a clear error if it is missing or of the wrong type.
  const nlohmann::json& field(const std::string& json_pointer) const;
  std::uint64_t count(const std::string& json_pointer) const;
  [[noreturn]] void fail(const std::string& problem) const { throw InputError(source_, problem); }

 private:
  struct SectionEntry {
    std::string name, dtype;
    std::uint64_t offset, bytes, elements, columns;
  };
  const SectionEntry& section(const std::string& name) const;
  std::uint64_t checked_count(const std::string& name, const char* dtype, std::uint64_t rows,
                              std::uint64_t columns) const;
  void copy_section(const std::string& name, void* out, std::size_t bytes) const;
  void parse_section_table(std::uint64_t data_start);

  std::string source_;
  FileKind kind_{};
  std::uint32_t version_ = 0;
  InputBytes bytes_;
  nlohmann::json meta_;
  std::vector<SectionEntry> sections_;
};

// Hash values travel as 16-digit hex strings in JSON (exact, unlike JSON numbers in numpy).
std::string hash_hex(std::uint64_t hash);
std::uint64_t parse_hash_hex(const std::string& text, const Container& from);

}  // namespace ncv
