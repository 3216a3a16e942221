#include "files/container.hpp"

#include <spdlog/spdlog.h>

#include <fmt/format.h>
#include <xxhash.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <memory>
#include <new>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "util/input_bytes.hpp"
#include "util/parallel_over.hpp"

namespace ncv {
namespace {

constexpr std::array<char, 8> kMagic = {'N', 'C', 'V', 'E', 'R', 'I', 'F', 'Y'};
constexpr std::uint64_t kHeaderBytes = 64;
constexpr std::uint64_t kTrailerBytes = 8;
constexpr std::uint64_t kAlignment = 64;

std::uint64_t align_up(std::uint64_t value) {
  return (value + kAlignment - 1) / kAlignment * kAlignment;
}

template <class T>
T load(const char* at) {
  T value;
  std::memcpy(&value, at, sizeof(T));
  return value;
}

template <class T>
void store(char* at, T value) {
  std::memcpy(at, &value, sizeof(T));
}

std::size_t dtype_width(const std::string& dtype) {
  if (dtype == "<f8" || dtype == "<u8") return 8;
  if (dtype == "<u4" || dtype == "<f4") return 4;
  if (dtype == "<u2") return 2;
  if (dtype == "<u1") return 1;
  return 0;
}

constexpr std::array<FileKind, 3> kAllKinds = {FileKind::samples, FileKind::grid,
                                               FileKind::distances};

}  // namespace

std::uint32_t format_version(FileKind kind) {
  switch (kind) {
    case FileKind::samples:
      return kSamplesFormatVersion;
    case FileKind::grid:
      return kGridFormatVersion;
    case FileKind::distances:
      return kDistancesFormatVersion;
  }
  return 0;
}

std::string kind_tag(FileKind kind) {
  switch (kind) {
    case FileKind::samples:
      return "SMPL";
    case FileKind::grid:
      return "GRID";
    case FileKind::distances:
      return "DIST";
  }
  return "????";
}

std::string kind_description(FileKind kind) {
  switch (kind) {
    case FileKind::samples:
      return "samples file";
    case FileKind::grid:
      return "grid file";
    case FileKind::distances:
      return "distance file";
  }
  return "unknown file";
}

std::string hash_hex(std::uint64_t hash) {
  return fmt::format("{:016x}", hash);
}

std::uint64_t parse_hash_hex(const std::string& text, const Container& from) {
  if (text.size() != 16 || text.find_first_not_of("0123456789abcdef") != std::string::npos) {
    from.fail(fmt::format("malformed hash '{}' in metadata", text));
  }
  return std::stoull(text, nullptr, 16);
}

// ---------------------------------------------------------------- writing

ContainerWriter::ContainerWriter(FileKind kind, std::uint32_t version, nlohmann::json meta)
    : kind_(kind), version_(version), meta_(std::move(meta)) {}

void ContainerWriter::add_raw(std::string name, const char* dtype, std::size_t width,
                              const void* data, std::uint64_t bytes,
                              std::vector<std::uint64_t> shape) {
  sections_.push_back({std::move(name), dtype, width, data, bytes, std::move(shape)});
}

namespace {

constexpr std::size_t kGrain = std::size_t{1} << 16;

bool is_float(double x) {
  return static_cast<double>(static_cast<float>(x)) == x;
}

}  // namespace

void ContainerWriter::add_counts(std::string name, std::span<const std::uint32_t> counts) {
  const std::uint32_t largest = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, counts.size(), 1 << 16), std::uint32_t{0},
      [&](const auto& range, std::uint32_t most) {
        for (std::size_t i = range.begin(); i != range.end(); ++i) most = std::max(most, counts[i]);
        return most;
      },
      [](std::uint32_t a, std::uint32_t b) { return std::max(a, b); });
  const auto add_as = [&]<class T>(T) {
    const std::span<T> narrow = kept_array<T>(counts.size());
    parallel_over(counts.size(), kGrain,
                  [&](std::size_t i) { narrow[i] = static_cast<T>(counts[i]); });
    add<T>(std::move(name), std::span<const T>(narrow), {narrow.size()});
  };
  if (largest <= 0xff) {
    add_as(std::uint8_t{});
  } else if (largest <= 0xffff) {
    add_as(std::uint16_t{});
  } else {
    add_as(std::uint32_t{});
  }
}

void ContainerWriter::add_points(std::string name, std::span<const Vec3> points) {
  const bool floats = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, points.size(), 1 << 16), true,
      [&](const auto& range, bool all) {
        for (std::size_t i = range.begin(); all && i != range.end(); ++i) {
          all = is_float(points[i][0]) && is_float(points[i][1]) && is_float(points[i][2]);
        }
        return all;
      },
      [](bool a, bool b) { return a && b; });
  if (!floats) {
    add<double>(std::move(name),
                {reinterpret_cast<const double*>(points.data()), points.size() * 3},
                {points.size(), 3});
    return;
  }
  const std::span<float> flat = kept_array<float>(points.size() * 3);
  parallel_over(points.size(), kGrain, [&](std::size_t i) {
    for (int k = 0; k < 3; ++k)
      flat[3 * i + static_cast<std::size_t>(k)] = static_cast<float>(points[i][k]);
  });
  add<float>(std::move(name), std::span<const float>(flat), {points.size(), 3});
}

std::uint64_t ContainerWriter::write(OutputFile& out) {
  // The section offsets depend on the metadata's length, which contains them: iterate
  // until the start of the data no longer moves (two or three rounds).
  std::string meta_text;
  std::uint64_t data_start = 0;
  std::vector<std::uint64_t> offsets(sections_.size());
  for (int round = 0; round < 8; ++round) {
    std::uint64_t at = data_start;
    nlohmann::json table = nlohmann::json::array();
    for (std::size_t s = 0; s < sections_.size(); ++s) {
      offsets[s] = at;
      table.push_back({{"name", sections_[s].name},
                       {"dtype", sections_[s].dtype},
                       {"shape", sections_[s].shape},
                       {"offset", at},
                       {"bytes", sections_[s].bytes}});
      at = align_up(at + sections_[s].bytes);
    }
    meta_["sections"] = table;
    meta_text = meta_.dump(1);
    const std::uint64_t start = align_up(kHeaderBytes + meta_text.size());
    if (start == data_start) break;
    data_start = start;
  }
  const std::uint64_t data_end =
      sections_.empty() ? data_start : offsets.back() + sections_.back().bytes;
  const std::uint64_t file_bytes = data_end + kTrailerBytes;

  std::array<char, kHeaderBytes> header{};
  std::memcpy(header.data(), kMagic.data(), kMagic.size());
  std::memcpy(header.data() + 8, kind_tag(kind_).data(), 4);
  store<std::uint32_t>(header.data() + 12, version_);
  store<std::uint64_t>(header.data() + 16, meta_text.size());
  store<std::uint64_t>(header.data() + 24, file_bytes);

  // Owned, so that a write that throws (a full disk) does not leak it.
  const std::unique_ptr<XXH3_state_t, decltype(&XXH3_freeState)> owned_state(XXH3_createState(),
                                                                             &XXH3_freeState);
  if (!owned_state) throw std::bad_alloc();
  XXH3_state_t* state = owned_state.get();
  XXH3_64bits_reset(state);
  std::uint64_t written = 0;
  auto emit = [&](const void* data, std::uint64_t bytes) {
    XXH3_64bits_update(state, data, bytes);
    out.write(data, bytes);
    written += bytes;
  };
  const std::array<char, kAlignment> zeros{};
  auto pad_to = [&](std::uint64_t offset) { emit(zeros.data(), offset - written); };

  emit(header.data(), header.size());
  emit(meta_text.data(), meta_text.size());
  for (std::size_t s = 0; s < sections_.size(); ++s) {
    pad_to(offsets[s]);
    emit(sections_[s].data, sections_[s].bytes);
  }
  const std::uint64_t hash = XXH3_64bits_digest(state);
  out.write(&hash, sizeof hash);
  return hash;
}

// ---------------------------------------------------------------- reading

std::uint64_t Container::content_hash() const {
  return load<std::uint64_t>(bytes_.data() + bytes_.size() - kTrailerBytes);
}

Container Container::read(const std::string& path, FileKind kind, std::uint32_t version) {
  Container c = parse(read_input_bytes(path), input_name(path), kind, version);
  spdlog::debug("read {}: {} version {}, {} bytes, content hash {}", c.source(), kind_tag(kind),
                version, c.bytes_.size(), hash_hex(c.content_hash()));
  return c;
}

Container Container::read_any(const std::string& path) {
  InputBytes bytes = read_input_bytes(path);
  FileKind kind = FileKind::samples;
  if (bytes.size() >= 12) {
    for (FileKind candidate : kAllKinds) {
      if (std::memcmp(bytes.data() + 8, kind_tag(candidate).data(), 4) == 0) kind = candidate;
    }
  }
  return parse(std::move(bytes), input_name(path), kind, format_version(kind));
}

Container Container::parse(InputBytes bytes, const std::string& source, FileKind kind,
                           std::uint32_t version) {
  Container c;
  c.source_ = source;
  c.kind_ = kind;
  c.bytes_ = std::move(bytes);
  const std::uint64_t size = c.bytes_.size();
  const char* data = c.bytes_.data();
  if (size == 0) c.fail("empty file, expected an ncverify " + kind_description(kind));
  if (size < kMagic.size() || std::memcmp(data, kMagic.data(), kMagic.size()) != 0) {
    c.fail("not an ncverify file (no NCVERIFY magic number); expected a " + kind_description(kind));
  }
  if (size < kHeaderBytes + kTrailerBytes) c.fail("truncated: shorter than the header");
  if (std::memcmp(data + 8, kind_tag(kind).data(), 4) != 0) {
    std::string found = "an unknown kind of ncverify file";
    for (FileKind other : kAllKinds) {
      if (std::memcmp(data + 8, kind_tag(other).data(), 4) == 0) {
        found = "a " + kind_description(other);
      }
    }
    c.fail("is " + found + ", expected a " + kind_description(kind));
  }
  c.version_ = load<std::uint32_t>(data + 12);
  if (c.version_ != version) {
    c.fail(fmt::format("{} format version {} is {} than this ncverify reads (version {}): {}",
                       kind_description(kind), c.version_, c.version_ > version ? "newer" : "older",
                       version,
                       c.version_ > version ? "use the ncverify that wrote it"
                                            : "make it again with this ncverify"));
  }
  const auto meta_bytes = load<std::uint64_t>(data + 16);
  const auto file_bytes = load<std::uint64_t>(data + 24);
  if (file_bytes > size) {
    c.fail(
        fmt::format("truncated: the header says {} bytes, only {} are present", file_bytes, size));
  }
  if (file_bytes < size) {
    c.fail(fmt::format("{} unexpected bytes after the end of the file", size - file_bytes));
  }
  const auto stored_hash = load<std::uint64_t>(data + size - kTrailerBytes);
  if (XXH3_64bits(data, size - kTrailerBytes) != stored_hash) {
    c.fail("content hash mismatch: the file is corrupted");
  }
  if (meta_bytes > size - kHeaderBytes - kTrailerBytes) c.fail("metadata length out of range");
  c.meta_ =
      nlohmann::json::parse(data + kHeaderBytes, data + kHeaderBytes + meta_bytes, nullptr, false);
  if (!c.meta_.is_object()) c.fail("metadata is not a JSON object");
  c.parse_section_table(kHeaderBytes + meta_bytes);
  return c;
}

void Container::parse_section_table(std::uint64_t data_start) {
  const nlohmann::json& table = field("/sections");
  if (!table.is_array()) fail("section table is not an array");
  const std::uint64_t data_end = bytes_.size() - kTrailerBytes;
  for (const auto& entry : table) {
    SectionEntry s;
    std::vector<std::uint64_t> shape;
    bool counts_are_integers = false;
    try {
      s.name = entry.at("name").get<std::string>();
      s.dtype = entry.at("dtype").get<std::string>();
      // get<std::uint64_t>() converts any JSON number: a float beyond 2^64 is undefined
      // behaviour (found by fuzz_distance_file), 64.5 would become 64. Only JSON's
      // non-negative integers are offsets, sizes and dimensions.
      const nlohmann::json& offset = entry.at("offset");
      const nlohmann::json& bytes = entry.at("bytes");
      const nlohmann::json& dimensions = entry.at("shape");
      counts_are_integers =
          offset.is_number_unsigned() && bytes.is_number_unsigned() && dimensions.is_array() &&
          std::all_of(dimensions.begin(), dimensions.end(),
                      [](const nlohmann::json& d) { return d.is_number_unsigned(); });
      if (counts_are_integers) {
        s.offset = offset.get<std::uint64_t>();
        s.bytes = bytes.get<std::uint64_t>();
        shape = dimensions.get<std::vector<std::uint64_t>>();
      }
    } catch (const nlohmann::json::exception&) {
      counts_are_integers = false;
    }
    if (!counts_are_integers) fail("malformed section table entry");
    const std::size_t width = dtype_width(s.dtype);
    if (width == 0) fail(fmt::format("section '{}' has unknown dtype '{}'", s.name, s.dtype));
    if (s.offset < data_start || s.offset > data_end || s.bytes > data_end - s.offset ||
        s.offset % kAlignment != 0 || s.bytes % width != 0) {
      fail(fmt::format("section '{}' lies outside the file", s.name));
    }
    s.elements = s.bytes / width;
    s.columns = 1;
    std::uint64_t product = shape.empty() ? 0 : shape[0];
    for (std::size_t k = 1; k < shape.size(); ++k) {
      if (shape[k] == 0 || product > s.elements / shape[k]) {
        fail(fmt::format("section '{}' has a shape its size does not match", s.name));
      }
      product *= shape[k];
      s.columns *= shape[k];
    }
    if (product != s.elements) {
      fail(fmt::format("section '{}' has a shape its size does not match", s.name));
    }
    sections_.push_back(std::move(s));
  }
}

bool Container::has(const std::string& name) const {
  for (const auto& s : sections_) {
    if (s.name == name) return true;
  }
  return false;
}

const Container::SectionEntry& Container::section(const std::string& name) const {
  for (const auto& s : sections_) {
    if (s.name == name) return s;
  }
  fail(fmt::format("section '{}' is missing", name));
}

std::uint64_t Container::checked_count(const std::string& name, const char* dtype,
                                       std::uint64_t rows, std::uint64_t columns) const {
  const SectionEntry& s = section(name);
  if (s.dtype != dtype) {
    fail(fmt::format("section '{}' has dtype {}, expected {}", name, s.dtype, dtype));
  }
  // rows came from the metadata: compare in a way that cannot overflow.
  if (columns == 0 || rows > s.elements / columns || rows * columns != s.elements) {
    fail(fmt::format("section '{}' holds {} values, the metadata implies {} × {}", name, s.elements,
                     rows, columns));
  }
  return s.elements;
}

std::vector<std::uint32_t> Container::get_counts(const std::string& name,
                                                 std::uint64_t rows) const {
  if (!has(name)) fail(fmt::format("section '{}' is missing", name));
  const std::string& type = dtype(name);
  if (type == "<u1") {
    const auto narrow = get<std::uint8_t>(name, rows);
    return {narrow.begin(), narrow.end()};
  }
  if (type == "<u2") {
    const auto narrow = get<std::uint16_t>(name, rows);
    return {narrow.begin(), narrow.end()};
  }
  return get<std::uint32_t>(name, rows);
}

std::vector<Vec3> Container::get_points(const std::string& name, std::uint64_t rows) const {
  if (!has(name)) fail(fmt::format("section '{}' is missing", name));
  if (dtype(name) != "<f4") return get_rows<double, Vec3>(name, rows);
  const std::vector<float> flat = get<float>(name, rows * 3);
  std::vector<Vec3> points(rows, Vec3(0, 0, 0));
  for (std::size_t i = 0; i < points.size(); ++i) {
    points[i] = Vec3(flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]);
  }
  return points;
}

void Container::copy_section(const std::string& name, void* out, std::size_t bytes) const {
  const SectionEntry& s = section(name);
  if (bytes) std::memcpy(out, bytes_.data() + s.offset, bytes);
}

Container::RawSection Container::raw_section(const std::string& name) const {
  const SectionEntry& s = section(name);
  return {s.dtype, s.elements, s.columns, bytes_.data() + s.offset};
}

const nlohmann::json& Container::field(const std::string& json_pointer) const {
  const nlohmann::json::json_pointer pointer(json_pointer);
  if (!meta_.contains(pointer)) fail(fmt::format("metadata field {} is missing", json_pointer));
  return meta_.at(pointer);
}

std::uint64_t Container::count(const std::string& json_pointer) const {
  const nlohmann::json& value = field(json_pointer);
  if (!value.is_number_unsigned() &&
      !(value.is_number_integer() && value.get<std::int64_t>() >= 0)) {
    fail(fmt::format("metadata field {} is not a count", json_pointer));
  }
  return value.get<std::uint64_t>();
}

}  // namespace ncv
