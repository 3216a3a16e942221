#include "render/error_mesh.hpp"

#include <limits>

#include <fmt/format.h>

#include "sampling/lattice_triangles.hpp"
#include "util/error.hpp"

namespace ncv {

namespace {

constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

std::uint32_t vertex_index(std::uint64_t sample) {
  return static_cast<std::uint32_t>(sample);
}

}  // namespace

ErrorMesh workpiece_error_mesh(const SampleSet& samples, std::span<const double> d,
                               std::span<const std::uint32_t> sample_region) {
  const std::size_t vertices = samples.mesh.vertex_count();
  ErrorMesh out{samples.mesh, std::vector<double>(vertices, kNoValue),
                std::vector<std::uint32_t>(vertices, kNoRegion)};
  for (std::size_t v = 0; v < vertices; ++v) {
    const std::uint32_t s = samples.vertex_sample[v];
    if (s == kNoSample) continue;
    out.values[v] = d[s];
    if (!sample_region.empty()) out.regions[v] = sample_region[s];
  }
  return out;
}

ErrorMesh lattice_error_mesh(const SampleSet& samples, std::span<const double> d,
                             std::span<const std::uint32_t> sample_region) {
  // PLY face lists hold signed 32-bit vertex indices.
  if (samples.sample_count() + samples.mesh.vertex_count() >
      std::uint64_t{std::numeric_limits<std::int32_t>::max()}) {
    throw UsageError(
        fmt::format("{} samples are too many for one PLY mesh; use the workpiece "
                    "vertices instead of the lattice",
                    samples.sample_count()));
  }
  ErrorMesh out{{samples.positions, {}},
                std::vector<double>(d.begin(), d.end()),
                sample_region.empty()
                    ? std::vector<std::uint32_t>(d.size(), kNoRegion)
                    : std::vector<std::uint32_t>(sample_region.begin(), sample_region.end())};
  const Mesh& workpiece = samples.mesh;
  std::vector<std::uint32_t> extra_vertex(workpiece.vertex_count(), kNoSample);
  const auto corner_vertex = [&](std::uint32_t v) {
    if (samples.vertex_sample[v] != kNoSample) return samples.vertex_sample[v];
    if (extra_vertex[v] == kNoSample) {
      extra_vertex[v] = static_cast<std::uint32_t>(out.mesh.vertices.size());
      out.mesh.vertices.push_back(workpiece.vertices[v]);
      out.values.push_back(kNoValue);
      out.regions.push_back(kNoRegion);
    }
    return extra_vertex[v];
  };
  for (std::size_t t = 0; t < workpiece.triangle_count(); ++t) {
    if (samples.lattice_sizes[t] == 0) {
      const Triangle& corners = workpiece.triangles[t];
      out.mesh.triangles.push_back(
          {corner_vertex(corners[0]), corner_vertex(corners[1]), corner_vertex(corners[2])});
      continue;
    }
    for_each_lattice_triangle(samples, t, [&](std::uint64_t a, std::uint64_t b, std::uint64_t c) {
      out.mesh.triangles.push_back({vertex_index(a), vertex_index(b), vertex_index(c)});
    });
  }
  return out;
}

}  // namespace ncv
