#include <array>
#include <memory>
#include <string>

#include "commands.hpp"
#include "ncgen/analytic_parts.hpp"
#include "part_files.hpp"

namespace ncv::gen::app {

void add_box_command(CLI::App& app) {
  struct Options {
    std::string output;
    std::array<double, 3> dims{100, 60, 30};
    double offset = 0;
    double top_offset = 0;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "box", "A box on the origin (the nominal), or one with faces moved by a known amount");
  command->add_option("-o,--output", options->output, "STL file to write")->required();
  command->add_option("--dims", options->dims, "Box size x y z, mm")->capture_default_str();
  CLI::Option* offset = command->add_option(
      "--offset", options->offset, "Moves every face outwards by this much (negative: inwards)");
  command->add_option("--top-offset", options->top_offset, "Moves the top face up by this much")
      ->excludes(offset);
  command->callback([options] {
    const auto& [x, y, z] = options->dims;
    const double a = options->offset;
    save_mesh(box_mesh({-a, -a, -a}, {x + a, y + a, z + a + options->top_offset}), options->output,
              "ncgen box");
  });
}

void add_scallop_command(CLI::App& app) {
  struct Options {
    std::string output;
    std::array<double, 3> dims{100, 60, 30};
    double radius = 1.5;
    double stepover = 0.625;
    int segments = 4;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command =
      app.add_subcommand("scallop",
                         "The box with its top cut by ball-end passes along x: scallops of height "
                         "R - sqrt(R^2 - (s/2)^2) above the nominal top");
  command->add_option("-o,--output", options->output, "STL file to write")->required();
  command->add_option("--dims", options->dims, "Box size x y z, mm")->capture_default_str();
  command->add_option("--radius", options->radius, "Ball radius R, mm")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  command->add_option("--stepover", options->stepover, "Distance s between passes, mm")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  command->add_option("--segments", options->segments, "Chords per half arc")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  command->callback([options] {
    const auto& [x, y, z] = options->dims;
    save_mesh(scalloped_box({x, y, z}, options->radius, options->stepover, options->segments),
              options->output, "ncgen scalloped box");
  });
}

}  // namespace ncv::gen::app
