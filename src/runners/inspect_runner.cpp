#include "runners/inspect_runner.hpp"

#include <fmt/format.h>

#include <cstring>

#include "files/container.hpp"
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
  for (std::uint64_t r = 0; r < shown; ++r) {
    fmt::format_to(std::back_inserter(line), "{}", r);
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
    write_records(c, options, out);
  } else {
    write_header_text(c, input_name(options.file), out);
    if (options.head >= 0 && c.meta().contains("records")) write_records(c, options, out);
  }
  out.commit();
}

}  // namespace ncv
