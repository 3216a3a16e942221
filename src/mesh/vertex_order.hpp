// Vertex numbering in a spatial order where a file's own order scatters.
//
// A mesh is welded in the order its file lists the corners. Where the facets come in random
// order (some exporters write them so), a triangle's corners get numbers far apart, and every
// pass that goes vertex by vertex or reads a triangle's corners' values jumps across memory:
// the samples are numbered vertex by vertex (docs/FORMATS.md), so the distance search loses
// its hint from one sample to the next, and the statistics read each triangle's corner values
// from three distant places. Renumbering the vertices in Morton order of their positions puts
// neighbours next to each other. The triangles keep their order and orientation, so every sum
// taken triangle by triangle, and every value, is the same to the bit; only the numbering of
// the vertices (and with it of the vertex samples) changes.
#pragma once

#include <cstddef>

#include "mesh/mesh.hpp"

namespace ncv {

// Below this many vertices a mesh's values fit the caches whatever the order: left as read.
inline constexpr std::size_t kLeastVerticesToOrder = std::size_t{1} << 16;

// True when the mesh has at least kLeastVerticesToOrder vertices and its triangles' corners
// lie, at the median over up to 4096 triangles spread evenly through the list, more than a
// sixteenth of the numbering apart (largest index minus smallest). Welded in file order,
// meshes written neighbour after neighbour measure below 0.004 and ones with their facets
// shuffled about 0.37.
bool vertices_scattered(const Mesh& mesh);

// Renumbers the vertices in Morton order of their cells (64 an axis over the bounding box;
// within a cell, by the old number), renaming the triangles' corners alike. Deterministic
// whatever the thread count.
void order_vertices_spatially(Mesh& mesh);

}  // namespace ncv
