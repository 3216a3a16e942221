#include <memory>
#include <string>

#include "commands.hpp"
#include "meshing_options.hpp"
#include "ncgen/nominal_part.hpp"
#include "ncgen/placement.hpp"
#include "part_files.hpp"

namespace ncv::gen::app {

void add_nominal_command(CLI::App& app, const GlobalOptions& global) {
  struct Options {
    std::string output;
    NominalOptions nominal;
    MeshingOptions meshing;
    std::size_t triangles = decimated_nominal_triangles;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "nominal", "The mould core as a CAD system exports it (about 17 k triangles at 0.08 mm)");
  command->add_option("-o,--output", options->output, "STL file to write")->required();
  command->add_option("--tolerance", options->nominal.chord_tolerance, "Chord tolerance, mm")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  command
      ->add_option("--level", options->nominal.level,
                   "Height samples: 2^level cells per 40 mm tile")
      ->capture_default_str()
      ->check(CLI::Range(4, 11));
  add_meshing_options(*command, options->meshing);
  command
      ->add_option("--triangles", options->triangles,
                   "decimate: triangles of the nominal (the RTIN's follow from --tolerance)")
      ->capture_default_str()
      ->check(CLI::Range(1000, 10'000'000));
  command->callback([options, &global] {
    const MouldCore part = make_mould_core(global.seed);
    const Meshing meshing = options->meshing.meshing();
    const Placement placement = options->meshing.placement(global.seed);
    if (meshing.mesher == Mesher::decimate) {
      save_part(mesh_decimated_nominal(part, options->triangles, meshing), placement,
                options->output);
      return;
    }
    ncv::Mesh mesh = nominal_mesh(part, options->nominal);
    place(mesh, placement);
    save_mesh(mesh, options->output, "ncgen mould core nominal");
  });
}

}  // namespace ncv::gen::app
