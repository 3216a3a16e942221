// Reading a mesh file into a welded Mesh. The format is detected from the content, not the
// name: a binary STL whose 80-byte header starts with "solid" is still binary.
//   STL binary and ASCII: parsed here (the hot path for large simulated workpieces),
//     vertices welded by exact coordinate equality (-0 = +0), first-seen order.
//   PLY, OBJ, OFF: parsed strictly in double precision by polygon_reader (which says why
//     not OpenMesh), the file's vertex indices kept, polygons fan-triangulated.
// Either way, a large mesh whose numbering scatters (facets in random order) then has its
// vertices renumbered in a spatial order (vertex_order.hpp); the triangles keep theirs.
// Every fault (empty, truncated, size mismatch, NaN/Inf, no triangles, not a mesh) throws
// InputError naming the source.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "mesh/mesh.hpp"

namespace ncv {

enum class MeshFormat { stl_binary, stl_ascii, ply, obj, off };

std::string format_name(MeshFormat format);

struct MeshReadReport {
  MeshFormat format = MeshFormat::stl_binary;
  std::uint64_t degenerate_triangles = 0;  // zero area after welding
};

// Logs (debug, shown with -v) the format, the counts and the zero-area triangles.
Mesh read_mesh(const std::string& path);
Mesh parse_mesh(std::span<const char> bytes, const std::string& source,
                MeshReadReport* report = nullptr);

}  // namespace ncv
