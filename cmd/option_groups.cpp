#include "option_groups.hpp"

#include <charconv>
#include <cmath>

#include "options.hpp"
#include "statistics/value_range.hpp"

namespace ncv::cmd {
namespace {

double parse_positive_length(const std::string& text) {
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() ||
      !std::isfinite(value) || !(value > 0)) {
    throw UsageError("'" + text + "' is not a positive length in model units");
  }
  return value;
}

}  // namespace

void add_sample_options(CLI::App& sub, SampleOptions& options) {
  add_parsed_option(sub, "-s,--step", options.step, SamplingStep::parse,
                    "Sampling step: model units (0.05) or % of the bounding-box diagonal (0.1%)")
      ->default_str(options.step.text());
  add_enum_option(sub, "--scheme", options.scheme, kSamplingSchemeNames,
                  "all: tiny triangles give their vertices (paper scheme I); paper-ii: they are "
                  "skipped (the paper's baseline)");
  sub.add_flag("--force", options.force, "Sample even when the sample count looks unreasonable");
}

void add_grid_options(CLI::App& sub, GridOptions& options) {
  add_parsed_option(sub, "--cell", options.cell_size, parse_positive_length,
                    "Grid cell edge in model units (default: the edge of the equilateral "
                    "triangle of the mean triangle area)");
}

void add_distance_options(CLI::App& sub, DistanceOptions& options) {
  add_enum_option(sub, "--sign", options.sign, kSignMethodNames,
                  "auto: pseudonormal for a closed oriented nominal, else winding number; "
                  "paper: the sample's own normal (the paper's rule)");
  sub.add_flag("--brute-force", options.brute_force,
               "Test every nominal triangle for every sample (the reference; slow)");
  add_parsed_option(sub, "--certify", options.certify->width, parse_positive_length,
                    "Width of the certified interval for the max and the min error between "
                    "samples, in model units (default: 0.001)");
  add_count_option(sub, "--certify-points", options.certify->points_cap, 0, kMaxCertifyPoints,
                   "Most points certification may add by refinement (0: as many as the lattice "
                   "has samples, at least 20000)");
}

void add_tolerance_option(CLI::App& sub, std::optional<Tolerance>& tolerance,
                          const std::string& description) {
  add_parsed_option(sub, "-t,--tol", tolerance, parse_tolerance, description);
}

void add_report_options(CLI::App& sub, ReportOptions& options) {
  add_count_option(sub, "--bins", options.histogram.bins, 1, kMaxHistogramBins, "Histogram bins");
  add_parsed_option(sub, "--histogram-range", options.histogram.range, parse_value_range,
                    "Histogram range LO:HI (default: d_min to d_max)");
  add_count_option(sub, "--regions", options.regions, 0, kMaxListedRegions,
                   "Out-of-tolerance regions listed in the text");
  add_units_option(sub, options.units);
}

void add_one_sided_option(CLI::App& sub, ReportOptions& options) {
  sub.add_flag("--one-sided", options.one_sided,
               "Judge one direction's distance file on its own (without it, a part measured in "
               "one direction that passes is inconclusive: the other direction may fail)");
}

void add_report_file_options(CLI::App& sub, ReportFiles& files) {
  sub.add_option("--regions-csv", files.regions_csv,
                 "Also list every out-of-tolerance region as CSV");
  sub.add_option("--histogram-csv", files.histogram_csv, "Also write the histogram as CSV");
}

void add_units_option(CLI::App& sub, std::string& units) {
  sub.add_option("--units", units, "Units of the model's coordinates, named in the reports")
      ->capture_default_str();
}

void add_samples_file_option(CLI::App& sub, std::string& samples) {
  sub.add_option("--samples", samples,
                 "The samples file of the distance file, when it is not where the distance file "
                 "says");
}

void add_color_map_options(CLI::App& sub, ColorizeOptions& options) {
  add_parsed_option(
      sub, "--map", options.map,
      [](const std::string& text) {
        const auto kind = parse_name(kColorMapNames, text);
        if (!kind) {
          throw UsageError("'" + text + "' is not one of " + names_list(kColorMapNames));
        }
        return *kind;
      },
      "Colour map: tolerance (green within, red excess, blue gouge), diverging "
      "(blue-white-red) or turbo; default: tolerance when --tol is given")
      ->type_name("NAME");
  add_parsed_option(sub, "--range", options.range, parse_value_range,
                    "Values the colour map spans, LO:HI or R for ±R (default: from the data)");
}

void add_colorize_options(CLI::App& sub, ColorizeOptions& options) {
  add_color_map_options(sub, options);
  sub.add_flag("--coarse", options.coarse,
               "Write the mesh's own vertices only (a small file; errors inside its triangles, "
               "the worst point among them, do not show); default: the sampling lattice, every "
               "sample a vertex");
}

}  // namespace ncv::cmd
