// ncverify distance SAMPLES GRID -o OUT.dist: exact signed distance of every sample.
#include <spdlog/spdlog.h>

#include "command_options.hpp"
#include "commands.hpp"
#include "files/distance_file.hpp"
#include "files/grid_file.hpp"
#include "files/samples_file.hpp"
#include "search/search_index.hpp"
#include "steps/distance_step.hpp"
#include "util/input_bytes.hpp"

namespace ncv::cmd {
namespace {

struct DistanceOptions {
  std::string samples;
  std::string grid;
  std::string output;
  DistanceStepOptions step;
};

// Output opened first and the report after the commit, as in `sample`.
void run_distance(const DistanceOptions& options) {
  OutputFile out(default_output(options.output, options.samples, ".dist"), OutputKind::binary);
  SampleSet samples = read_samples_file(options.samples);
  const PreparedNominal grid = read_grid_file(options.grid);
  double seconds = 0;
  const DistanceSet result = [&] {  // the search's boxes freed before the file is written
    const SearchIndex search(grid.nominal->corners(), grid.grid);
    return measure_distances(std::move(samples), grid, search, options.step, &seconds);
  }();
  write_distance_file(result, out);
  out.commit();
  log_distance_report(result, seconds);
  spdlog::info("wrote {}", out.display_name());
}

}  // namespace

void add_distance_command(CLI::App& app, CommandContext&) {
  auto options = std::make_shared<DistanceOptions>();
  CLI::App* sub =
      app.add_subcommand("distance", "Signed distance from every sample to the nominal");
  sub->add_option("samples", options->samples, "Samples file from `sample` (- = stdin)")
      ->required();
  sub->add_option("grid", options->grid, "Grid file from `grid-build`")->required();
  add_output_option(*sub, options->output, "Distance file (default: SAMPLES stem + .dist)");
  add_distance_options(*sub, options->step);
  sub->callback([options] { run_distance(*options); });
}

}  // namespace ncv::cmd
