#include "render/error_mesh.hpp"

#include <algorithm>
#include <limits>
#include <utility>

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "sampling/lattice_triangles.hpp"
#include "util/block_offsets.hpp"
#include "util/error.hpp"

namespace ncv {

namespace {

constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();
constexpr std::uint64_t kFacesPerBlock = 1 << 12;

std::uint32_t vertex_index(std::uint64_t sample) {
  return static_cast<std::uint32_t>(sample);
}

}  // namespace

ErrorMeshPly::ErrorMeshPly(const Mesh& mesh, std::span<const double> values,
                           std::span<const std::uint32_t> regions)
    : mesh_(mesh), values_(values), regions_(regions) {
  const std::uint64_t faces = mesh.triangle_count();
  for (std::uint64_t f = 0; f < faces; f += kFacesPerBlock) offsets_.push_back(f);
  offsets_.push_back(faces);
}

void ErrorMeshPly::group_faces(std::size_t g, Triangle* out) const {
  const auto begin = mesh_.triangles.begin() + static_cast<std::ptrdiff_t>(offsets_[g]);
  std::copy(begin, begin + static_cast<std::ptrdiff_t>(offsets_[g + 1] - offsets_[g]), out);
}

VertexErrors vertex_errors(const SampleSet& samples, std::span<const double> d,
                           std::span<const std::uint32_t> sample_region) {
  const std::size_t vertices = samples.mesh.vertex_count();
  VertexErrors out{std::vector<double>(vertices), std::vector<std::uint32_t>(vertices)};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vertices, 1 << 14), [&](const auto& r) {
    for (std::size_t v = r.begin(); v != r.end(); ++v) {
      const std::uint32_t s = samples.vertex_sample[v];
      out.values[v] = s == kNoSample ? kNoValue : d[s];
      out.regions[v] = s == kNoSample || sample_region.empty() ? kNoRegion : sample_region[s];
    }
  });
  return out;
}

ErrorMesh workpiece_error_mesh(const SampleSet& samples, std::span<const double> d,
                               std::span<const std::uint32_t> sample_region) {
  VertexErrors errors = vertex_errors(samples, d, sample_region);
  return {samples.mesh, std::move(errors.values), std::move(errors.regions)};
}

LatticeMesh::LatticeMesh(const SampleSet& samples, std::span<const double> d,
                         std::span<const std::uint32_t> sample_region)
    : samples_(samples),
      d_(d),
      sample_region_(sample_region),
      extra_vertex_(samples.mesh.vertex_count(), kNoSample) {
  // PLY face lists hold signed 32-bit vertex indices.
  if (samples.sample_count() + samples.mesh.vertex_count() >
      std::uint64_t{std::numeric_limits<std::int32_t>::max()}) {
    throw UsageError(
        fmt::format("{} samples are too many for one PLY mesh; use the workpiece "
                    "vertices instead of the lattice",
                    samples.sample_count()));
  }
  const Mesh& workpiece = samples.mesh;
  for (std::size_t t = 0; t < workpiece.triangle_count(); ++t) {
    if (samples.lattice_sizes[t] != 0) continue;
    for (const std::uint32_t v : workpiece.triangles[t]) {
      if (samples.vertex_sample[v] != kNoSample || extra_vertex_[v] != kNoSample) continue;
      extra_vertex_[v] = static_cast<std::uint32_t>(samples.sample_count() + extra_.size());
      extra_.push_back(v);
    }
  }
  first_face_ = block_offsets(workpiece.triangle_count(), [&](std::size_t t) {
    const std::uint32_t n = samples.lattice_sizes[t];
    return n == 0 ? 1 : lattice_triangle_count(n);
  });
}

PlyVertex LatticeMesh::vertex(std::uint64_t v) const {
  if (v < samples_.sample_count()) {
    return {samples_.positions[v], d_[v], sample_region_.empty() ? kNoRegion : sample_region_[v]};
  }
  return {samples_.mesh.vertices[extra_[v - samples_.sample_count()]], kNoValue, kNoRegion};
}

// An unsampled triangle (scheme II) on its corners, a sampled one as its sub-triangles.
void LatticeMesh::group_faces(std::size_t t, Triangle* out) const {
  if (samples_.lattice_sizes[t] == 0) {
    const auto corner = [&](std::uint32_t v) {
      return samples_.vertex_sample[v] != kNoSample ? samples_.vertex_sample[v] : extra_vertex_[v];
    };
    const Triangle& corners = samples_.mesh.triangles[t];
    *out = {corner(corners[0]), corner(corners[1]), corner(corners[2])};
    return;
  }
  for_each_lattice_triangle(samples_, t, [&](std::uint64_t a, std::uint64_t b, std::uint64_t c) {
    *out++ = {vertex_index(a), vertex_index(b), vertex_index(c)};
  });
}

ErrorMesh lattice_error_mesh(const SampleSet& samples, std::span<const double> d,
                             std::span<const std::uint32_t> sample_region) {
  const LatticeMesh lattice(samples, d, sample_region);
  const std::uint64_t vertices = lattice.vertex_count();
  ErrorMesh out;
  out.mesh.vertices.resize(vertices);
  out.values.resize(vertices);
  out.regions.resize(vertices);
  tbb::parallel_for(tbb::blocked_range<std::uint64_t>(0, vertices, 1 << 14),
                    [&](const auto& range) {
                      for (std::uint64_t v = range.begin(); v != range.end(); ++v) {
                        const PlyVertex vertex = lattice.vertex(v);
                        out.mesh.vertices[v] = vertex.point;
                        out.values[v] = vertex.value;
                        out.regions[v] = vertex.region;
                      }
                    });
  const std::span<const std::uint64_t> first = lattice.face_offsets();
  out.mesh.triangles.resize(first.back());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, first.size() - 1, 4096),
                    [&](const auto& range) {
                      for (std::size_t t = range.begin(); t != range.end(); ++t) {
                        lattice.group_faces(t, out.mesh.triangles.data() + first[t]);
                      }
                    });
  return out;
}

}  // namespace ncv
