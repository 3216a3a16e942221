// Binary little-endian PLY of a coloured error mesh for MeshLab and CloudCompare
// (docs/METHOD.md "Colouring"). Per vertex: float x y z (model coordinates), uchar red green blue
// baked from the colour map, float quality (MeshLab's per-vertex quality) and float
// scalar_signed_distance (CloudCompare's scalar field), both the signed error, NaN where
// no sample lies, and int scalar_region: the out-of-tolerance region the vertex lies in (k
// for the report's k-th region, 0 for none), so a viewer can select one region by value.
// Faces: list uchar int vertex_indices.
#pragma once

#include <span>
#include <string>

#include "render/color_map.hpp"
#include "render/ply_mesh.hpp"
#include "util/output_file.hpp"

namespace ncv {

// Writes the whole file to out (not committed). comments become header comment lines (line
// breaks replaced by blanks), followed by one describing the colour map. The fixed-size
// records are made in parallel a chunk of a few megabytes at a time and written before the
// next: an image of the whole file was 64 MB of freshly faulted memory for each of the
// finishing job's two PLYs, copied into the kernel from a cold buffer.
void write_error_ply(OutputFile& out, const PlyMesh& mesh, const ColorMap& map,
                     std::span<const std::string> comments = {});

}  // namespace ncv
