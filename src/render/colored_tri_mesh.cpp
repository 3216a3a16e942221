#include "render/colored_tri_mesh.hpp"

namespace ncv {

TriMesh colored_tri_mesh(const ErrorMesh& error_mesh, const ColorMap& map) {
  std::vector<std::uint32_t> copied_from;
  TriMesh mesh = tri_mesh(error_mesh.mesh, &copied_from);
  mesh.request_vertex_colors();
  OpenMesh::VPropHandleT<double> error;
  mesh.add_property(error, kSignedErrorProperty);
  mesh.property(error).set_persistent(true);
  for (const auto vertex : mesh.all_vertices()) {
    const double value = error_mesh.values[copied_from[vertex.idx()]];
    const Rgb rgb = map.rgb(value);
    mesh.set_color(vertex, TriMesh::Color(rgb[0], rgb[1], rgb[2]));
    mesh.property(error, vertex) = value;
  }
  return mesh;
}

}  // namespace ncv
