// A mesh as the coloured PLY shows it, read where it lies rather than copied into a file
// image first: each vertex's point, error value and region, and the faces in groups (a
// workpiece triangle's lattice sub-triangles, or a block of a face list) that the writer
// asks for a few megabytes at a time (render/ply_writer.hpp).
#pragma once

#include <cstdint>
#include <span>

#include "geometry/vec3.hpp"
#include "mesh/mesh.hpp"

namespace ncv {

struct PlyVertex {
  Vec3 point;
  double value;          // NaN where no sample lies
  std::uint32_t region;  // k + 1 for the report's k-th region, kNoRegion elsewhere
};

class PlyMesh {
 public:
  virtual ~PlyMesh() = default;
  virtual std::uint64_t vertex_count() const = 0;
  virtual PlyVertex vertex(std::uint64_t v) const = 0;
  // Group g holds the faces [face_offsets()[g], face_offsets()[g + 1]); the last offset is
  // the face count.
  virtual std::span<const std::uint64_t> face_offsets() const = 0;
  // Writes group g's faces, in order, to out[0 .. its face count).
  virtual void group_faces(std::size_t g, Triangle* out) const = 0;
};

}  // namespace ncv
