// Options of the coloured output (colorize and run) and the writing of the PLY and legend.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "files/distance_file.hpp"

namespace ncv::cmd {

struct ColorizeOptions {
  std::string tolerance;  // shared with the report in `run`
  std::string map;        // tolerance, diverging, turbo; default: tolerance when one is given
  std::string range;      // "lo:hi" or "r" for ±r; default from the data
  bool refine = false;
  std::string legend_svg;
};

void add_colorize_options(CLI::App& sub, ColorizeOptions& options);
void write_colorized(const DistanceSet& distances, const std::string& ply_path,
                     const ColorizeOptions& options);

}  // namespace ncv::cmd
