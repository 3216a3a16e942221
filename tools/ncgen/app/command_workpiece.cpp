#include <memory>
#include <string>

#include "commands.hpp"
#include "meshing_options.hpp"
#include "ncgen/part_size.hpp"
#include "ncgen/workpiece.hpp"
#include "part_files.hpp"

namespace ncv::gen::app {

void add_workpiece_command(CLI::App& app, const GlobalOptions& global) {
  struct Options {
    std::string output;
    std::string stage;
    std::string size = "small";
    std::string report;
    MeshingOptions meshing;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "workpiece", "The mould core after simulated milling up to and including a stage");
  command->add_option("-o,--output", options->output, "STL file to write")->required();
  command->add_option("--stage", options->stage, "roughing, semi or finishing")
      ->required()
      ->check(CLI::IsMember({"roughing", "semi", "semi-finishing", "semifinishing", "finishing"}));
  command
      ->add_option("--size", options->size,
                   "small, medium, large (the paper's triangle counts) or a factor of large")
      ->capture_default_str();
  command->add_option("--report", options->report,
                      "JSON file describing the process, tolerance and gouges");
  add_meshing_options(*command, options->meshing);
  command->callback([options, &global] {
    const double size = parse_size(options->size);
    const Meshing meshing = options->meshing.meshing();
    const Placement placement = options->meshing.placement(global.seed);
    std::vector<MillingStage> stages = mould_core_stages();
    stages.resize(stage_index(options->stage) + 1);
    mill_part(make_mould_core(global.seed), size, stages,
              [&](const MillingStage& stage, const MillingSimulation& simulation) {
                if (stage.name != stages.back().name) return;
                const nlohmann::json json =
                    save_workpiece(stage, simulation, size, options->output, meshing, placement);
                if (!options->report.empty()) write_json(json, options->report);
              });
  });
}

}  // namespace ncv::gen::app
