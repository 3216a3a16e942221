#include "runners/inspect_runner.hpp"

#include <fmt/format.h>

#include <cstring>

#include "files/container.hpp"
#include "files/samples_file.hpp"
#include "util/error.hpp"
#include "util/input_bytes.hpp"
#include "util/output_file.hpp"

namespace ncv {
namespace {

// One column of the record table: a section, or one component of an N×3 section.
struct Column {
  std::string name;
  Container::RawSection section;
  std::uint64_t width;      // values per record
  std::uint64_t component;  // which of them
};

std::string format_value(const Container::RawSection& s, std::uint64_t index) {
  if (s.dtype == "<u1") return fmt::format("{}", static_cast<std::uint8_t>(s.data[index]));
  if (s.dtype == "<u2") {
    std::uint16_t v;
    std::memcpy(&v, s.data + 2 * index, 2);
    return fmt::format("{}", v);
  }
  const char* at = s.data + index * (s.dtype == "<u4" ? 4 : 8);
  if (s.dtype == "<f8") {
    double v;
    std::memcpy(&v, at, 8);
    return fmt::format("{}", v);
  }
  if (s.dtype == "<u8") {
    std::uint64_t v;
    std::memcpy(&v, at, 8);
    return fmt::format("{}", v);
  }
  std::uint32_t v;
  std::memcpy(&v, at, 4);
  return fmt::format("{}", v);
}

std::vector<Column> record_columns(const Container& c, std::uint64_t records) {
  std::vector<Column> columns;
  if (!c.meta().contains("records")) {
    throw UsageError(fmt::format("a {} has no per-record table; see its header (--json)",
                                 kind_description(c.kind())));
  }
  const nlohmann::json& names = c.field("/records/sections");
  if (!names.is_array()) c.fail("record table is malformed");
  for (const auto& name : names) {
    if (!name.is_string()) c.fail("record table is malformed");
    const auto section = c.raw_section(name.get<std::string>());
    const std::uint64_t width = section.columns;
    if (section.elements / width != records) c.fail("record section size mismatch");
    for (std::uint64_t k = 0; k < width; ++k) {
      const std::string suffix = width == 1   ? std::string()
                                 : width == 3 ? fmt::format("_{}", "xyz"[k])
                                              : fmt::format("_{}", k);
      columns.push_back({name.get<std::string>() + suffix, section, width, k});
    }
  }
  return columns;
}

void write_records(const Container& c, const InspectJob& options, OutputFile& out) {
  const std::vector<Column> columns =
      record_columns(c, c.meta().contains("records") ? c.count("/records/count") : 0);
  const std::uint64_t records = c.count("/records/count");
  const std::uint64_t shown =
      options.head >= 0 ? std::min<std::uint64_t>(records, options.head) : records;
  const char separator = options.csv ? ',' : '\t';
  fmt::memory_buffer line;
  fmt::format_to(std::back_inserter(line), "index");
  for (const Column& column : columns) {
    fmt::format_to(std::back_inserter(line), "{}{}", separator, column.name);
  }
  line.push_back('\n');
  // A shard's records are samples first .. first + records - 1 of its job.
  const std::uint64_t first = c.meta()["records"].contains("first") ? c.count("/records/first") : 0;
  for (std::uint64_t r = 0; r < shown; ++r) {
    fmt::format_to(std::back_inserter(line), "{}", first + r);
    for (const Column& column : columns) {
      fmt::format_to(std::back_inserter(line), "{}{}", separator,
                     format_value(column.section, r * column.width + column.component));
    }
    line.push_back('\n');
    if (line.size() > (1u << 20)) {
      out.write(line.data(), line.size());
      line.clear();
    }
  }
  out.write(line.data(), line.size());
}

// A samples file stores the mesh and the lattice sizes; its samples are made again to show
// them, one row each.
void write_samples(const Container& c, const InspectJob& options, OutputFile& out) {
  const SampleSet set = load_sample_set(c);
  const std::uint64_t shown = options.head >= 0
                                  ? std::min<std::uint64_t>(set.sample_count(), options.head)
                                  : set.sample_count();
  const char separator = options.csv ? ',' : '\t';
  fmt::memory_buffer line;
  fmt::format_to(std::back_inserter(line),
                 "index{0}positions_x{0}positions_y{0}positions_z{0}"
                 "owner{0}lattice_i{0}lattice_j\n",
                 separator);
  for (std::uint64_t k = 0; k < shown; ++k) {
    const Vec3& p = set.positions[k];
    fmt::format_to(std::back_inserter(line), "{1}{0}{2}{0}{3}{0}{4}{0}{5}{0}{6}{0}{7}\n", separator,
                   set.first_sample + k, p[0], p[1], p[2], set.owner[k], set.lattice_i[k],
                   set.lattice_j[k]);
    if (line.size() > (1u << 20)) {
      out.write(line.data(), line.size());
      line.clear();
    }
  }
  out.write(line.data(), line.size());
}

void write_header_text(const Container& c, const std::string& name, OutputFile& out) {
  out.write(fmt::format("file:    {} ({} bytes)\n", name, c.file_bytes()));
  out.write(fmt::format("kind:    {} ({}), format version {}\n", kind_tag(c.kind()),
                        kind_description(c.kind()), c.version()));
  nlohmann::json meta = c.meta();
  const nlohmann::json sections = meta["sections"];
  meta.erase("sections");
  for (const auto& [key, value] : meta.items()) {
    out.write(fmt::format("{}: {}\n", key, value.dump()));
  }
  out.write("sections:\n");
  for (const auto& s : sections) {
    out.write(fmt::format("  {:<20} {} shape {} at offset {} ({} bytes)\n",
                          s["name"].get<std::string>(), s["dtype"].get<std::string>(),
                          s["shape"].dump(), s["offset"].dump(), s["bytes"].dump()));
  }
}

}  // namespace

void run_inspect(const InspectJob& options) {
  const Container c = Container::read_any(options.file);
  OutputFile out(options.output, OutputKind::text);
  if (options.json) {
    const nlohmann::json header = {{"file", input_name(options.file)},
                                   {"bytes", c.file_bytes()},
                                   {"kind", kind_tag(c.kind())},
                                   {"format_version", c.version()},
                                   {"meta", c.meta()}};
    out.write(header.dump(2) + "\n");
  } else if (options.csv) {
    c.kind() == FileKind::samples ? write_samples(c, options, out) : write_records(c, options, out);
  } else {
    write_header_text(c, input_name(options.file), out);
    if (options.head >= 0 && c.kind() == FileKind::samples) write_samples(c, options, out);
    if (options.head >= 0 && c.meta().contains("records")) write_records(c, options, out);
  }
  out.commit();
}

}  // namespace ncv
