#include "options.hpp"

#include <fmt/format.h>

#include <charconv>

#include "commands.hpp"

#include <filesystem>

namespace ncv::cmd {

std::string option_display_name(const std::string& names) {
  const std::size_t comma = names.rfind(',');
  return comma == std::string::npos ? names : names.substr(comma + 1);
}

std::uint64_t parse_count(const std::string& text, std::uint64_t min, std::uint64_t max) {
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() || value < min ||
      value > max) {
    throw UsageError(fmt::format("'{}' is not a whole number from {} to {}", text, min, max));
  }
  return value;
}

std::string default_output(const std::string& output, const std::string& input,
                           const std::string& extension) {
  if (!output.empty()) return output;
  if (input == "-") return "-";
  return std::filesystem::path(input).stem().string() + extension;
}

void add_output_option(CLI::App& sub, std::string& output, const std::string& description) {
  sub.add_option("-o,--output", output, description + "; - = standard output");
}

std::string quoted_command_line(int argc, char** argv) {
  static constexpr std::string_view kPlain =
      "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-+=/.,:%@";
  std::string line;
  for (int k = 0; k < argc; ++k) {
    const std::string_view arg = argv[k];
    if (k > 0) line += ' ';
    if (!arg.empty() && arg.find_first_not_of(kPlain) == std::string_view::npos) {
      line += arg;
      continue;
    }
    line += '\'';
    for (const char c : arg) line += c == '\'' ? std::string("'\\''") : std::string(1, c);
    line += '\'';
  }
  return line;
}

}  // namespace ncv::cmd
