// The options `workpiece` and `nominal` share for the second family and for placing a part:
// --mesher, --refinement, --tolerance-factor, --shuffle and --shift.
#pragma once

#include <CLI/CLI.hpp>

#include <array>
#include <cstdint>
#include <string>

#include "part_files.hpp"

namespace ncv::gen::app {

struct MeshingOptions {
  std::string mesher = "rtin";
  DecimatedOptions decimated;
  bool shuffle = false;
  std::array<double, 3> shift{0, 0, 0};

  Meshing meshing() const;
  // The shuffle seeded by the global seed.
  Placement placement(std::uint64_t seed) const;
};

void add_meshing_options(CLI::App& command, MeshingOptions& options);

}  // namespace ncv::gen::app
