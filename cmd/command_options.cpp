#include "command_options.hpp"

#include <filesystem>

#include "error.hpp"

namespace ncv::cmd {

SamplingScheme parse_scheme_option(const std::string& name) {
  if (name == "all") return SamplingScheme::all;
  if (name == "paper-ii") return SamplingScheme::paper_ii;
  throw UsageError("unknown scheme '" + name + "': use all or paper-ii");
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

void add_step_options(CLI::App& sub, std::string& step, std::string& scheme) {
  sub.add_option("-s,--step", step,
                 "Sampling step: model units (0.05) or % of the bounding-box diagonal (0.1%)")
      ->capture_default_str();
  sub.add_option("--scheme", scheme,
                 "all: tiny triangles give their vertices (paper scheme I); paper-ii: they are "
                 "skipped (the paper's baseline)")
      ->check(CLI::IsMember({"all", "paper-ii"}))
      ->capture_default_str();
}

void add_distance_options(CLI::App& sub, DistanceStepOptions& options) {
  const std::map<std::string, SignMethod> methods = {{"auto", SignMethod::automatic},
                                                     {"pseudonormal", SignMethod::pseudonormal},
                                                     {"winding", SignMethod::winding},
                                                     {"paper", SignMethod::paper}};
  sub.add_option("--sign", options.sign,
                 "auto: pseudonormal for a closed oriented nominal, else winding number; "
                 "paper: the sample's own normal (the paper's rule)")
      ->transform(CLI::CheckedTransformer(methods))
      ->default_str("auto");
  sub.add_flag("--brute-force", options.brute_force,
               "Test every nominal triangle for every sample (the reference; slow)");
}

}  // namespace ncv::cmd
