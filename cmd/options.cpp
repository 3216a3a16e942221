#include "options.hpp"

#include <filesystem>

namespace ncv::cmd {

std::string option_display_name(const std::string& names) {
  const std::size_t comma = names.rfind(',');
  return comma == std::string::npos ? names : names.substr(comma + 1);
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

}  // namespace ncv::cmd
