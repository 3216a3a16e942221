#include "ncgen/decimation.hpp"

#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>

#include <limits>

#include "ncgen/decimation_mesh.hpp"
#include "ncgen/height_field_guard.hpp"
#include "ncgen/sample_bound.hpp"
#include "ncgen/valence_cap.hpp"

namespace ncv::gen {
namespace {

constexpr std::uint32_t no_vertex = std::numeric_limits<std::uint32_t>::max();

bool on_border(const Grid& grid, std::uint32_t sample) {
  const auto row = static_cast<std::uint32_t>(grid.samples_x());
  const auto i = static_cast<int>(sample % row);
  const auto j = static_cast<int>(sample / row);
  return i == 0 || j == 0 || i == grid.cells_x() || j == grid.cells_y();
}

// The triangles as a DecimationMesh whose vertex property `sample` names each vertex's grid sample.
DecimationMesh build_mesh(const Grid& grid, const std::vector<float>& heights,
                          const std::vector<GridTriangle>& triangles,
                          OpenMesh::VPropHandleT<std::uint32_t>& sample) {
  DecimationMesh mesh;
  mesh.add_property(sample);
  // Ours, so that the deleted faces can still be told apart once the decimater, which
  // requests the flags too, has released them.
  mesh.request_vertex_status();
  mesh.request_face_status();
  std::vector<std::uint32_t> vertex_of_sample(grid.sample_count(), no_vertex);
  const auto row = static_cast<std::uint32_t>(grid.samples_x());
  for (const GridTriangle& t : triangles) {
    for (const std::uint32_t s : t) {
      if (vertex_of_sample[s] != no_vertex) continue;
      const auto vertex = mesh.add_vertex(
          {grid.x(static_cast<int>(s % row)), grid.y(static_cast<int>(s / row)), heights[s]});
      mesh.property(sample, vertex) = s;
      vertex_of_sample[s] = static_cast<std::uint32_t>(vertex.idx());
    }
  }
  // A disc of F triangles has 3F/2 edges and half its border's more: reserved, the kernel's
  // arrays (2.6 M faces on the large finishing part) are not copied as they grow.
  mesh.reserve(mesh.n_vertices(), 3 * triangles.size() / 2 + grid.samples_x() + grid.samples_y(),
               triangles.size());
  for (const GridTriangle& t : triangles) {
    mesh.add_face(OpenMesh::VertexHandle(static_cast<int>(vertex_of_sample[t[0]])),
                  OpenMesh::VertexHandle(static_cast<int>(vertex_of_sample[t[1]])),
                  OpenMesh::VertexHandle(static_cast<int>(vertex_of_sample[t[2]])));
  }
  return mesh;
}

}  // namespace

Decimation decimate_height_field(const Grid& grid, const std::vector<float>& heights,
                                 const std::vector<GridTriangle>& triangles,
                                 const std::vector<std::uint32_t>& keep,
                                 const DecimationOptions& options) {
  OpenMesh::VPropHandleT<std::uint32_t> sample;
  DecimationMesh mesh = build_mesh(grid, heights, triangles, sample);
  Decimation result;
  {
    OpenMesh::Decimater::DecimaterT<DecimationMesh> decimater(mesh);
    std::vector<bool> kept(grid.sample_count(), false);
    for (const std::uint32_t s : keep) kept[s] = true;
    for (const auto vertex : mesh.vertices()) {
      const std::uint32_t s = mesh.property(sample, vertex);
      if (kept[s] || on_border(grid, s)) mesh.status(vertex).set_locked(true);
    }
    // Binary modules run in the order added and stop at the first refusal: the cheap checks
    // first, the sample bound last (it measures every sample removed around the collapse, and
    // needs the top a height field, which the guard keeps).
    ValenceCapT<DecimationMesh>::Handle cap;
    HeightFieldGuardT<DecimationMesh>::Handle guard;
    SampleBoundT<DecimationMesh>::Handle bound;
    OpenMesh::Decimater::ModQuadricT<DecimationMesh>::Handle quadric;
    decimater.add(cap);
    decimater.add(guard);
    decimater.add(bound);
    decimater.add(quadric);
    decimater.module(bound).set_tolerance(options.tolerance);
    decimater.initialize();
    result.collapses = decimater.decimate_to_faces(0, options.target);
  }
  result.triangles.reserve(mesh.n_faces());
  for (const auto face : mesh.faces()) {
    if (mesh.status(face).deleted()) continue;
    GridTriangle& t = result.triangles.emplace_back();
    int k = 0;
    for (const auto vertex : mesh.fv_range(face)) t[k++] = mesh.property(sample, vertex);
  }
  return result;
}

}  // namespace ncv::gen
