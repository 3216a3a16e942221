#include <memory>
#include <string>

#include "commands.hpp"
#include "ncgen/nominal_part.hpp"
#include "part_files.hpp"

namespace ncv::gen::app {

void add_nominal_command(CLI::App& app, const GlobalOptions& global) {
  struct Options {
    std::string output;
    NominalOptions nominal;
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
  command->callback([options, &global] {
    const ncv::Mesh mesh = nominal_mesh(make_mould_core(global.seed), options->nominal);
    save_mesh(mesh, options->output, "ncgen mould core nominal");
  });
}

}  // namespace ncv::gen::app
