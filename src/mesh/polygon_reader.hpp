// PLY, OFF and OBJ parsed by ncverify itself, strictly, into a Mesh with the file's own
// vertex indices (no welding) and every polygon fan-triangulated.
//
// Why not OpenMesh (which read these formats before): its readers round every coordinate
// to float (1000000.001 became 1000000, a silent error of the size of a machining
// tolerance for a part far from the origin), reserve memory for whatever counts a header
// claims, loop forever on a PLY header without end_header and on an OFF face count beyond
// the data, and skip or misread malformed numbers without saying so.
//
// Here coordinates are read as doubles, no memory is reserved from a count a file states
// (arrays grow with the data actually present, so a 1 kB file claiming 2^32 vertices
// fails as truncated), every number must parse completely, every face must have at least
// three corners that name existing vertices, and nothing may follow the last element.
// Each fault throws InputError(source, "FORMAT, line N: ...") (or "at byte N" in binary
// PLY). Accepted:
//   PLY  ascii, binary_little_endian and binary_big_endian; any scalar types; element
//        "vertex" with x, y, z; element "face" with a list "vertex_indices" (or
//        "vertex_index"); other elements and properties are read and ignored.
//   OFF  ASCII, with the ST/C/N prefixes (normals, colours and texture coordinates are
//        ignored), counts on the keyword's line or the next, '#' comments. 4OFF, nOFF and
//        binary OFF are refused.
//   OBJ  v (x y z, any further values ignored) and f (i, i/t, i//n, i/t/n, negative
//        indices counting back from the last vertex); '#' comments; other statements
//        (vt, vn, g, o, s, usemtl, mtllib, l, p, ...) are ignored.
#pragma once

#include <span>
#include <string>

#include "mesh/mesh.hpp"

namespace ncv {

Mesh parse_ply(std::span<const char> bytes, const std::string& source);
Mesh parse_off(std::span<const char> bytes, const std::string& source);
Mesh parse_obj(std::span<const char> bytes, const std::string& source);

}  // namespace ncv
