// A mesh carrying one error value per vertex, the input of the coloured PLY and of the HTML
// view, held in arrays (ErrorMesh) or read in place from the samples (LatticeMesh).
#pragma once

#include <span>
#include <vector>

#include "mesh/mesh.hpp"
#include "render/ply_mesh.hpp"
#include "sampling/sampling.hpp"
#include "statistics/error_regions.hpp"
#include "util/buffer.hpp"

namespace ncv {

struct ErrorMesh {
  Mesh mesh;
  std::vector<double> values;          // per vertex; NaN where no sample lies
  std::vector<std::uint32_t> regions;  // per vertex: its out-of-tolerance region (k + 1 for
                                       // the report's k-th region), kNoRegion elsewhere
};

// A mesh and its per-vertex values and regions as the PLY writer reads them, in place: its
// faces in blocks.
class ErrorMeshPly final : public PlyMesh {
 public:
  ErrorMeshPly(const Mesh& mesh, std::span<const double> values,
               std::span<const std::uint32_t> regions);
  explicit ErrorMeshPly(const ErrorMesh& mesh)
      : ErrorMeshPly(mesh.mesh, mesh.values, mesh.regions) {}
  std::uint64_t vertex_count() const override { return mesh_.vertex_count(); }
  PlyVertex vertex(std::uint64_t v) const override {
    return {mesh_.vertices[v], values_[v], regions_[v]};
  }
  std::span<const std::uint64_t> face_offsets() const override { return offsets_; }
  void group_faces(std::size_t g, Triangle* out) const override;

 private:
  const Mesh& mesh_;
  std::span<const double> values_;
  std::span<const std::uint32_t> regions_;
  std::vector<std::uint64_t> offsets_;
};

// sample_region (per sample, statistics/error_regions.hpp RegionMap) may be empty: no
// vertex is in a region then.
//
// Each vertex of the sampled mesh with the distance and region of its sample. A vertex no
// sampled triangle touches (scheme II) gets NaN: borrowing a value from elsewhere would
// paint a measurement that was never made.
struct VertexErrors {
  std::vector<double> values;
  std::vector<std::uint32_t> regions;
};
VertexErrors vertex_errors(const SampleSet& samples, std::span<const double> d,
                           std::span<const std::uint32_t> sample_region = {});

// The workpiece mesh itself with its vertex errors. Lattice points inside triangles are not
// shown.
ErrorMesh workpiece_error_mesh(const SampleSet& samples, std::span<const double> d,
                               std::span<const std::uint32_t> sample_region = {});

// The sampling lattice as a mesh: every sample a vertex (numbered as the samples), every
// lattice sub-triangle a face, so each sample's error is visible. Triangles that share an
// edge keep their own lattice points on it, so the mesh is not welded along such edges.
// Unsampled triangles (scheme II) are kept as they are, with NaN at corners no sample
// covers, so the shape stays whole: those corners are vertices after the samples, in order
// of first use. Read in place; face group t is workpiece triangle t's.
class LatticeMesh final : public PlyMesh {
 public:
  // Throws UsageError when the vertices would overflow the PLY's signed 32-bit indices.
  LatticeMesh(const SampleSet& samples, std::span<const double> d,
              std::span<const std::uint32_t> sample_region = {});
  std::uint64_t vertex_count() const override { return samples_.sample_count() + extra_.size(); }
  PlyVertex vertex(std::uint64_t v) const override;
  std::span<const std::uint64_t> face_offsets() const override { return first_face_; }
  void group_faces(std::size_t t, Triangle* out) const override;

 private:
  const SampleSet& samples_;
  std::span<const double> d_;
  std::span<const std::uint32_t> sample_region_;
  std::vector<std::uint32_t> extra_;         // workpiece vertices after the samples
  std::vector<std::uint32_t> extra_vertex_;  // per workpiece vertex: its vertex there, or kNoSample
  Buffer<std::uint64_t> first_face_;         // per workpiece triangle, and the face count
};

// The lattice mesh in arrays (the HTML view's, and OpenMesh's coloured mesh).
ErrorMesh lattice_error_mesh(const SampleSet& samples, std::span<const double> d,
                             std::span<const std::uint32_t> sample_region = {});

}  // namespace ncv
