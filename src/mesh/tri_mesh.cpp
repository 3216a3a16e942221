#include "mesh/tri_mesh.hpp"

#include <OpenMesh/Core/System/omstream.hh>
#include <array>
#include <numeric>

#include "util/error.hpp"

namespace ncv {
namespace {

bool has_deleted_elements(const TriMesh& mesh) {
  if (mesh.has_vertex_status()) {
    for (const auto v : mesh.all_vertices()) {
      if (mesh.status(v).deleted()) return true;
    }
  }
  if (mesh.has_face_status()) {
    for (const auto f : mesh.all_faces()) {
      if (mesh.status(f).deleted()) return true;
    }
  }
  return false;
}

// OpenMesh writes a line to its error stream for every face add_face refuses; tri_mesh()
// keeps such a face anyway, so the line would report a failure that did not happen.
class QuietOpenMeshErrors {
 public:
  QuietOpenMeshErrors() : was_enabled_(::omerr().is_enabled()) { ::omerr().disable(); }
  ~QuietOpenMeshErrors() {
    if (was_enabled_) ::omerr().enable();
  }
  QuietOpenMeshErrors(const QuietOpenMeshErrors&) = delete;
  QuietOpenMeshErrors& operator=(const QuietOpenMeshErrors&) = delete;

 private:
  bool was_enabled_;
};

}  // namespace

Mesh mesh_arrays(const TriMesh& mesh, const std::string& source) {
  if (has_deleted_elements(mesh)) {
    throw InputError(source, "the mesh has deleted elements: call garbage_collection() first");
  }
  Mesh arrays;
  arrays.vertices.assign(mesh.points(), mesh.points() + mesh.n_vertices());
  arrays.triangles.reserve(mesh.n_faces());
  for (const auto face : mesh.all_faces()) {
    Triangle triangle{};
    int k = 0;
    for (const auto vertex : face.vertices())
      triangle[k++] = static_cast<std::uint32_t>(vertex.idx());
    arrays.triangles.push_back(triangle);
  }
  check_mesh(arrays, source);
  return arrays;
}

TriMesh tri_mesh(const Mesh& mesh, std::vector<std::uint32_t>* copied_from) {
  TriMesh result;
  result.reserve(mesh.vertex_count(), 3 * mesh.triangle_count() / 2, mesh.triangle_count());
  for (const Vec3& p : mesh.vertices) result.add_vertex(p);
  std::vector<std::uint32_t> origin(mesh.vertex_count());
  std::iota(origin.begin(), origin.end(), 0u);

  const QuietOpenMeshErrors quiet;
  for (const Triangle& t : mesh.triangles) {
    std::array<TriMesh::VertexHandle, 3> corners;
    for (int k = 0; k < 3; ++k) corners[k] = TriMesh::VertexHandle(static_cast<int>(t[k]));
    const bool distinct = t[0] != t[1] && t[1] != t[2] && t[2] != t[0];
    if (distinct && result.add_face(corners[0], corners[1], corners[2]).is_valid()) continue;
    for (int k = 0; k < 3; ++k) {
      corners[k] = result.add_vertex(mesh.vertices[t[k]]);
      origin.push_back(t[k]);
    }
    result.add_face(corners[0], corners[1], corners[2]);
  }
  if (copied_from) *copied_from = std::move(origin);
  return result;
}

}  // namespace ncv
