// The grid file (kind GRID): the nominal mesh and its background grid, self-contained so
// `distance` needs nothing else. Layout in docs/FORMATS.md.
#pragma once

#include <memory>
#include <string>

#include "files/container.hpp"
#include "nominal/nominal_surface.hpp"
#include "search/background_grid.hpp"
#include "search/grid_builder.hpp"

namespace ncv {

// A nominal prepared for queries together with its grid, as grid-build makes it and
// distance reads it back.
struct PreparedNominal {
  std::unique_ptr<NominalSurface> nominal;
  BackgroundGrid grid;
  Mesh mesh;  // the nominal as read (global coordinates), what the file stores
  std::uint64_t nominal_hash = 0;
  std::string nominal_source;
};

// Prepares the nominal (topology, orientation, sign method) and builds its grid.
PreparedNominal build_nominal_grid(Mesh mesh, const std::string& source, const GridOptions& options,
                                   GridStatistics* statistics);

void write_grid_file(const PreparedNominal& grid, const GridStatistics& statistics,
                     OutputFile& out);
// Loads and validates (hash, indices, grid consistency) a grid file.
PreparedNominal read_grid_file(const std::string& path);
// The same from a parsed container (read_grid_file's second half; the fuzz target's entry).
PreparedNominal load_nominal_grid(const Container& container);

}  // namespace ncv
