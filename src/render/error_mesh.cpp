#include "render/error_mesh.hpp"

#include <limits>

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "sampling/lattice_triangles.hpp"
#include "util/block_offsets.hpp"
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
  ErrorMesh out{{std::vector<Vec3>(samples.positions.begin(), samples.positions.end()), {}},
                std::vector<double>(d.begin(), d.end()),
                sample_region.empty()
                    ? std::vector<std::uint32_t>(d.size(), kNoRegion)
                    : std::vector<std::uint32_t>(sample_region.begin(), sample_region.end())};
  const Mesh& workpiece = samples.mesh;
  // A triangle without a lattice (scheme II) is drawn on its corners; those without a sample
  // become vertices of their own, numbered in order of first use, before the faces are
  // written in parallel, each triangle's at its offset.
  const auto unsampled = [&](std::size_t t) { return samples.lattice_sizes[t] == 0; };
  std::vector<std::uint32_t> extra_vertex(workpiece.vertex_count(), kNoSample);
  for (std::size_t t = 0; t < workpiece.triangle_count(); ++t) {
    if (!unsampled(t)) continue;
    for (const std::uint32_t v : workpiece.triangles[t]) {
      if (samples.vertex_sample[v] != kNoSample || extra_vertex[v] != kNoSample) continue;
      extra_vertex[v] = static_cast<std::uint32_t>(out.mesh.vertices.size());
      out.mesh.vertices.push_back(workpiece.vertices[v]);
      out.values.push_back(kNoValue);
      out.regions.push_back(kNoRegion);
    }
  }
  const auto corner_vertex = [&](std::uint32_t v) {
    return samples.vertex_sample[v] != kNoSample ? samples.vertex_sample[v] : extra_vertex[v];
  };
  const Buffer<std::uint64_t> first = block_offsets(workpiece.triangle_count(), [&](std::size_t t) {
    return unsampled(t) ? 1 : lattice_triangle_count(samples.lattice_sizes[t]);
  });
  out.mesh.triangles.resize(first.back());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, workpiece.triangle_count(), 4096),
                    [&](const auto& range) {
                      for (std::size_t t = range.begin(); t != range.end(); ++t) {
                        Triangle* face = out.mesh.triangles.data() + first[t];
                        if (unsampled(t)) {
                          const Triangle& corners = workpiece.triangles[t];
                          *face = {corner_vertex(corners[0]), corner_vertex(corners[1]),
                                   corner_vertex(corners[2])};
                          continue;
                        }
                        for_each_lattice_triangle(
                            samples, t, [&](std::uint64_t a, std::uint64_t b, std::uint64_t c) {
                              *face++ = {vertex_index(a), vertex_index(b), vertex_index(c)};
                            });
                      }
                    });
  return out;
}

}  // namespace ncv
