#include "sampling/sample_normals.hpp"

namespace ncv {

std::vector<Vec3> vertex_normal_sums(const Mesh& mesh) {
  std::vector<Vec3> sums(mesh.vertex_count(), Vec3(0, 0, 0));
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const Vec3 weighted = area_vector(mesh, t);  // |cross| = twice the area
    for (std::uint32_t v : mesh.triangles[t]) sums[v] += weighted;
  }
  return sums;
}

std::vector<Vec3> sample_normals(const SampleSet& samples) {
  const Mesh& mesh = samples.mesh;
  const std::vector<Vec3> vertex_normals = vertex_normal_sums(mesh);
  // Per sample held: the samples numbered first .. first + count - 1 of the lattice.
  const std::uint64_t first = samples.first_sample, count = samples.sample_count();
  std::vector<Vec3> normals(count, Vec3(0, 0, 0));
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const std::uint64_t s = samples.vertex_sample[v];
    if (samples.vertex_sample[v] != kNoSample && s >= first && s - first < count) {
      normals[s - first] = normalized(vertex_normals[v]);
    }
  }
  for (std::size_t k = 0; k < count; ++k) {
    const std::uint64_t s = first + k;
    const std::uint32_t t = samples.owner[k];
    const bool is_corner = samples.vertex_sample[mesh.triangles[t][0]] == s ||
                           samples.vertex_sample[mesh.triangles[t][1]] == s ||
                           samples.vertex_sample[mesh.triangles[t][2]] == s;
    if (!is_corner) normals[k] = normalized(area_vector(mesh, t));
  }
  return normals;
}

}  // namespace ncv
