// The grid file (kind GRID): an IndexedReference (the mesh distances are measured to and its
// background grid), self-contained so `distance` needs nothing else. Layout in docs/FORMATS.md.
#pragma once

#include <memory>
#include <string>

#include "files/container.hpp"
#include "search/grid_builder.hpp"
#include "search/indexed_reference.hpp"

namespace ncv {

void write_grid_file(const IndexedReference& reference, const GridStatistics& statistics,
                     OutputFile& out);
// Loads and validates (hash, indices, grid consistency) a grid file.
IndexedReference read_grid_file(const std::string& path);
// The same from a parsed container (read_grid_file's second half; the fuzz target's entry).
IndexedReference load_indexed_reference(const Container& container);

}  // namespace ncv
