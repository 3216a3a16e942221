// ncverify grid-build NOMINAL -o OUT.grid: the background grid over the nominal (paper §3.3).
#include <spdlog/spdlog.h>

#include "command_options.hpp"
#include "commands.hpp"
#include "files/grid_file.hpp"
#include "mesh/mesh_reader.hpp"
#include "option_checks.hpp"
#include "util/input_bytes.hpp"
#include "util/memory_guard.hpp"
#include "util/stopwatch.hpp"

namespace ncv::cmd {
namespace {

struct GridBuildOptions {
  std::string nominal;
  std::string output;
  double cell_size = 0;
};

void report_grid(const PreparedNominal& g, const GridStatistics& s, double seconds) {
  const TopologyReport& t = g.nominal->topology();
  spdlog::info(
      "{}: {} triangles, {} vertices; closed: {}, manifold: {}, consistently oriented: "
      "{}; sign by {}",
      g.nominal_source, g.mesh.triangle_count(), g.mesh.vertex_count(), t.closed() ? "yes" : "no",
      t.manifold() ? "yes" : "no", t.consistently_oriented() ? "yes" : "no",
      sign_method_name(g.nominal->automatic_sign_method()));
  spdlog::info(
      "grid {}×{}×{} = {} cells of {} ({} empty), {} references ({:.2f} per triangle), "
      "{}, built in {:.3f} s",
      s.dims[0], s.dims[1], s.dims[2], s.cells, s.cell_size, s.empty_cells, s.references,
      s.references_per_triangle, format_bytes(s.bytes), seconds);
  if (s.growth_steps > 0) {
    spdlog::info("cell size grown from {} to {} to keep memory bounded", s.requested_cell_size,
                 s.cell_size);
  }
}

// Output opened first and the report after the commit, as in `sample`.
void run_grid_build(const GridBuildOptions& options) {
  Stopwatch clock;
  OutputFile out(default_output(options.output, options.nominal, ".grid"), OutputKind::binary);
  GridStatistics statistics;
  const PreparedNominal g =
      build_nominal_grid(read_mesh(options.nominal), input_name(options.nominal),
                         GridOptions{options.cell_size}, &statistics);
  write_grid_file(g, statistics, out);
  out.commit();
  report_grid(g, statistics, clock.seconds());
  spdlog::info("wrote {}", out.display_name());
}

}  // namespace

void add_grid_build_command(CLI::App& app, CommandContext&) {
  auto options = std::make_shared<GridBuildOptions>();
  CLI::App* sub = app.add_subcommand("grid-build", "Build the background grid of a nominal mesh");
  sub->add_option("nominal", options->nominal, "Nominal mesh (STL, PLY, OBJ, OFF; - = stdin)")
      ->required();
  add_output_option(*sub, options->output, "Grid file (default: NOMINAL stem + .grid)");
  sub->add_option("--cell", options->cell_size,
                  "Cell edge in model units (default: the edge of the equilateral triangle of "
                  "the mean nominal triangle area)")
      ->check(valid_positive_length());
  sub->callback([options] { run_grid_build(*options); });
}

}  // namespace ncv::cmd
