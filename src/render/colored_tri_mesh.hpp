// A coloured error mesh as an OpenMesh TriMesh, for a program that goes on working with it
// (include/ncverify/verify.hpp): each vertex with the colour the PLY bakes in
// (docs/METHOD.md "Colouring") as OpenMesh's vertex colour, and the signed error as the
// double vertex property kSignedErrorProperty, NaN where no sample lies.
#pragma once

#include "mesh/tri_mesh.hpp"
#include "render/color_map.hpp"
#include "render/error_mesh.hpp"

namespace ncv {

// Found with OpenMesh::VProp<double>(mesh, kSignedErrorProperty), or
// mesh.get_property_handle(handle, kSignedErrorProperty). Persistent, so OpenMesh's writers
// can store it as a custom property.
inline constexpr const char* kSignedErrorProperty = "signed_error";

// Every triangle of the error mesh is a face; where OpenMesh's halfedge structure cannot
// hold one (tri_mesh), its corner copies carry their vertex's colour and error.
TriMesh colored_tri_mesh(const ErrorMesh& error_mesh, const ColorMap& map);

}  // namespace ncv
