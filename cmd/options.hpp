// Declaring options whose text is parsed once, while the command line is read, into the typed
// fields of a runner's job (src/runners/): a value that does not parse is refused before any
// input is read or output written, in the parser's own words, with the option's name.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

#include "util/enum_names.hpp"
#include "util/error.hpp"

namespace ncv::cmd {

// The name CLI11 reports an option by: its last (long) name, "--tol" for "-t,--tol".
std::string option_display_name(const std::string& names);

// `parse(text)` returns the value or throws UsageError; its message becomes the refusal.
template <class Target, class Parse>
CLI::Option* add_parsed_option(CLI::App& sub, const std::string& names, Target& target, Parse parse,
                               const std::string& description) {
  return sub
      .add_option_function<std::string>(
          names,
          [&target, parse, shown = option_display_name(names)](const std::string& text) {
            try {
              target = parse(text);
            } catch (const UsageError& e) {
              throw CLI::ValidationError(shown, e.what());
            }
          },
          description)
      ->type_name("TEXT");
}

// An enum option spelt with the enum's one name table; the help lists the names.
template <class E, std::size_t N>
CLI::Option* add_enum_option(CLI::App& sub, const std::string& names, E& target,
                             const EnumName<E> (&table)[N], const std::string& description) {
  const std::string allowed = names_list(table);
  return add_parsed_option(
             sub, names, target,
             [&table, allowed](const std::string& text) {
               const auto value = parse_name(table, text);
               if (!value) throw UsageError("'" + text + "' is not one of " + allowed);
               return *value;
             },
             description + " (" + allowed + ")")
      ->type_name("NAME")
      ->default_str(std::string(name_of(table, target)));
}

// Bounds of the count options: far beyond any use, and small enough that what they size
// (a histogram's bins, a list's rows) stays within memory.
inline constexpr std::uint64_t kMaxHistogramBins = 100000;
inline constexpr std::uint64_t kMaxListedRegions = 1000000;
inline constexpr std::uint64_t kMaxThreads = 4096;
inline constexpr std::uint64_t kMaxHeadRecords = 1000000000000;
// Each point certification adds holds about 170 bytes of patches while it works.
inline constexpr std::uint64_t kMaxCertifyPoints = 50000000;

// A whole number from `min` to `max`, parsed into an integer field of any width; the help
// shows the range. The bounds keep every count's memory and time reasonable.
std::uint64_t parse_count(const std::string& text, std::uint64_t min, std::uint64_t max);
template <class Integer>
CLI::Option* add_count_option(CLI::App& sub, const std::string& names, Integer& target,
                              std::uint64_t min, std::uint64_t max,
                              const std::string& description) {
  return add_parsed_option(
             sub, names, target,
             [min, max](const std::string& text) {
               return static_cast<Integer>(parse_count(text, min, max));
             },
             description + " (" + std::to_string(min) + " to " + std::to_string(max) + ")")
      ->type_name("N")
      ->default_str(std::to_string(target));
}

// OUTPUT if given; else the input's stem + extension in the current folder, or "-" when
// the input is standard input.
std::string default_output(const std::string& output, const std::string& input,
                           const std::string& extension);
void add_output_option(CLI::App& sub, std::string& output, const std::string& description);

}  // namespace ncv::cmd
