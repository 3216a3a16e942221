// Declaring options whose text is parsed once, while the command line is read, into the typed
// fields of a runner's job (src/runners/): a value that does not parse is refused before any
// input is read or output written, in the parser's own words, with the option's name.
#pragma once

#include <CLI/CLI.hpp>
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

// OUTPUT if given; else the input's stem + extension in the current folder, or "-" when
// the input is standard input.
std::string default_output(const std::string& output, const std::string& input,
                           const std::string& extension);
void add_output_option(CLI::App& sub, std::string& output, const std::string& description);

}  // namespace ncv::cmd
